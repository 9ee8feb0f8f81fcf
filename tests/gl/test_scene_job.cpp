// The Scene panel's worker: loading and meshing off the UI thread, errors as text, cancellation.
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

TEST_CASE("a built-in scene loads and meshes on the worker, patches no larger than asked") {
    for (const double maxArea : {0.05, 0.01}) {
        SceneJob job;
        job.start("loading cornell-box", radiant::app::loadAndMesh("cornell-box", maxArea));
        const SceneJobResult result = waitFor(job);
        REQUIRE(result.scene.has_value());
        CHECK(result.error.empty());
        CHECK(result.maxPatchArea == maxArea);
        REQUIRE(result.mesh.size() > 0);
        double area = 0;
        for (const radiant::Patch& patch : result.mesh.patches) {
            CHECK(patch.area <= maxArea * (1 + 1e-9));
            area += patch.area;
        }
        // Meshing covers the surfaces exactly: patch areas sum to the scene's area.
        CHECK(area == doctest::Approx(result.scene->totalArea()).epsilon(1e-9));
        CHECK_FALSE(job.running());
    }
}

TEST_CASE("a bad path comes back as an error naming it, with no scene") {
    SceneJob job;
    job.start("loading", radiant::app::loadAndMesh("/nonexistent/box.gltf", 0.01));
    const SceneJobResult result = waitFor(job);
    CHECK_FALSE(result.scene.has_value());
    CHECK(result.error.find("/nonexistent/box.gltf") != std::string::npos);
}

TEST_CASE("a finer re-mesh replaces the job and the result is taken once") {
    SceneJob job;
    const radiant::Scene scene = radiant::loadScene("unit-cube").scene;
    job.start("meshing", radiant::app::remesh(scene, 0.25));
    job.start("meshing", radiant::app::remesh(scene, 0.0625));  // cancels or outlives the first
    const SceneJobResult result = waitFor(job);
    REQUIRE(result.scene.has_value());
    CHECK(result.maxPatchArea == 0.0625);
    CHECK(result.mesh.size() >= static_cast<std::size_t>(scene.totalArea() / 0.0625 - 1e-9));
    CHECK_FALSE(job.take().has_value());
}

}  // TEST_SUITE
