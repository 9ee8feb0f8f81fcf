// Ctrl+Z and Ctrl+Y in the lab: material edits undone and redone, the solve resuming to the answer it
// had before the edit (same form factors).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/Lab.h"
#include "radiometry/scene/Scene.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;
namespace command = radiant::app::command;

namespace {

LabOptions coarseCornellWindow() {
    LabOptions options;
    options.scene = "cornell-box";
    options.width = 640;
    options.height = 480;
    options.showPanels = false;
    options.vsync = false;
    options.maxPatchArea = 0.05;  // m^2: about a hundred patches
    options.runOnStart = false;
    return options;
}

Rgb reflectanceOf(const Lab& lab, std::size_t surface) {
    const Scene& scene = *lab.snapshot()->scene;
    return scene.materials[scene.surfaces[surface].material].reflectance;
}

/// Largest relative difference, over patches and bands, between two solutions of one mesh.
double largestRelativeDifference(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for (std::size_t p = 0; p < a.size(); ++p)
        for (int band = 0; band < 3; ++band)
            if (a[p][band] > 0) worst = std::max(worst, std::abs(a[p][band] - b[p][band]) / a[p][band]);
    return worst;
}

} // namespace

TEST_CASE("Ctrl+Z undoes material edits newest first and the solve returns to its answer, Ctrl+Y redoes") {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) FAIL("no X display: run the GL tests under Xvfb");
    Lab lab(coarseCornellWindow());
    lab.send(command::SetMethod{SolverMethod::GaussSeidel});
    lab.send(command::SetTolerance{1e-7});
    lab.send(command::Run{});
    lab.waitForSolver();
    lab.frame();
    const std::vector<Rgb> original = lab.snapshot()->radiosity;
    const std::uint64_t builds = lab.snapshot()->solverBuilds;
    const std::size_t floor = lab.snapshot()->scene->findSurface("floor");
    const std::size_t rightWall = lab.snapshot()->scene->findSurface("right wall");
    REQUIRE(floor != Scene::npos);
    REQUIRE(rightWall != Scene::npos);
    const Rgb floorReflectance = reflectanceOf(lab, floor);
    const Rgb wallReflectance = reflectanceOf(lab, rightWall);

    CHECK(lab.editMaterial(floor, Rgb(0.1), Rgb(0.0)).empty());
    CHECK(lab.editMaterial(rightWall, Rgb(0.63, 0.065, 0.05), Rgb(0.0)).empty());
    lab.waitForSolver();
    lab.frame();
    // The edits took: the solution moved well away from the original.
    CHECK(largestRelativeDifference(original, lab.snapshot()->radiosity) > 0.1);

    lab.pressKey(GLFW_KEY_Z, /*control=*/true);
    lab.waitForSolver();
    lab.frame();
    CHECK(reflectanceOf(lab, rightWall) == wallReflectance);
    CHECK(reflectanceOf(lab, floor) == Rgb(0.1));
    CHECK(lab.statusMessage().find("undid the edit of right wall") != std::string::npos);

    lab.pressKey(GLFW_KEY_Z, true);
    lab.waitForSolver();
    lab.frame();
    CHECK(reflectanceOf(lab, floor) == floorReflectance);
    // Converged again to 1e-7 from the edited solution: the same answer as before the edits.
    CHECK(largestRelativeDifference(original, lab.snapshot()->radiosity) < 1e-4);
    CHECK(lab.snapshot()->solverBuilds == builds);  // no form factors computed again

    lab.pressKey(GLFW_KEY_Z, true);  // nothing left to undo: said so, nothing changes
    CHECK(lab.statusMessage() == "no material edit to undo");
    lab.pressKey(GLFW_KEY_Y, true);
    lab.waitForSolver();
    lab.frame();
    CHECK(reflectanceOf(lab, floor) == Rgb(0.1));
    CHECK(reflectanceOf(lab, rightWall) == wallReflectance);
}
