// ctest-labels: threads
// The Scene panel's worker: loading off the UI thread, errors as text, the result taken once.
// (Meshing moved to the solver thread: tests/unit/test_solver_thread.cpp.)
#include <doctest/doctest.h>

#include <chrono>
#include <thread>

#include "app/panels/SceneJob.h"
#include "radiometry/scene/SceneLibrary.h"

using radiant::app::SceneJob;
using radiant::app::SceneJobResult;

namespace {
SceneJobResult waitFor(SceneJob& job) {
    for (int i = 0; i < 2000; ++i) {
        if (auto result = job.take()) return std::move(*result);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    FAIL("the scene job did not finish within 10 s");
    return {};
}
} // namespace

TEST_SUITE("scene panel") {

TEST_CASE("a built-in scene loads on the worker, the same scene the library loads") {
    SceneJob job;
    job.start("cornell-box");
    const SceneJobResult result = waitFor(job);
    REQUIRE(result.scene);
    CHECK(result.error.empty());
    const radiant::Scene direct = radiant::loadScene("cornell-box").scene;
    CHECK(result.scene->surfaces.size() == direct.surfaces.size());
    CHECK(result.scene->totalArea() == doctest::Approx(direct.totalArea()).epsilon(1e-12).scale(0));
    CHECK_FALSE(job.running());
}

TEST_CASE("a bad path comes back as an error naming it, with no scene") {
    SceneJob job;
    job.start("/nonexistent/box.gltf");
    const SceneJobResult result = waitFor(job);
    CHECK_FALSE(result.scene);
    CHECK(result.error.find("/nonexistent/box.gltf") != std::string::npos);
}

TEST_CASE("a second load replaces the first and the result is taken once") {
    SceneJob job;
    job.start("unit-cube");
    job.start("furnace");
    const SceneJobResult result = waitFor(job);
    REQUIRE(result.scene);
    CHECK(result.scene->name == "furnace");
    CHECK_FALSE(job.take().has_value());
}

}  // TEST_SUITE
