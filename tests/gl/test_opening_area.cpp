// The lab opens a scene at a patch area that follows its size (OpeningPatchArea.h) and groups by
// default where it pays (DefaultGrouping.h): a 57 m^2 room opens at 250 cm^2 as 2,694 patches in
// 2,335 unknowns solved by progressive refinement, no longer 61,935 patches and hierarchical sweeps;
// the Cornell box opens at the default, 2,248 patches at 13 cm^2, ungrouped.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "app/Lab.h"
#include "app/solver/SolverThread.h"
#include "radiometry/solver/SolveDefaults.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;
using radiant::test::frameUntil;
using radiant::test::requireDisplay;

namespace {

LabOptions opening(const std::string& scene) {
    LabOptions options;
    options.scene = scene;
    options.width = 1280;
    options.height = 800;
    options.vsync = false;
    options.runOnStart = false;  // the choice, not the solve, is under test
    return options;
}

} // namespace

TEST_SUITE("gl lab") {

TEST_CASE("the lab opens a room within progressive refinement's patch count, grouped where it pays, and the Cornell box at the default") {
    requireDisplay();
    {
        Lab lab(opening(RADIANT_TEST_DATA_DIR "/grouping/sphere_room.gltf"));
        frameUntil(lab, [](const app::Snapshot& s) { return s.mesh && s.solverBuilds >= 1; });
        const auto snapshot = lab.snapshot();
        CHECK(snapshot->meshing.maxPatchArea == doctest::Approx(0.025).epsilon(1e-12));
        CHECK(snapshot->mesh->size() == 2694);
        REQUIRE(snapshot->groups);
        CHECK(snapshot->groups->size() == 2335);
        CHECK(snapshot->method == SolverMethod::Progressive);
        INFO(snapshot->groupingReason);
        CHECK(snapshot->groupingReason.find("on: 2,694 patches in 2,335 groups") != std::string::npos);
    }
    {
        Lab lab(opening("cornell-box"));
        frameUntil(lab, [](const app::Snapshot& s) { return s.mesh && s.solverBuilds >= 1; });
        const auto snapshot = lab.snapshot();
        CHECK(snapshot->meshing.maxPatchArea == kSolveDefaults.maxPatchArea);
        CHECK(snapshot->mesh->size() == 2248);
        CHECK_FALSE(snapshot->groups);
        CHECK(snapshot->method == SolverMethod::Progressive);
    }
}

}  // TEST_SUITE
