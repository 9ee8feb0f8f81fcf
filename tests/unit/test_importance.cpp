// Importance-driven radiosity (Smits, Arvo, Salesin 1992) seen from a view that is an input: the
// scene's home view by default, any camera after, and an error - never a silent no-op - when the
// view sees no surface's front, so importance would be zero and nothing refined.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/solver/SolverThread.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/scene/View.h"
#include "radiometry/solver/ImportanceSolver.h"

using namespace radiant;

namespace {

PatchMesh meshAt(const Scene& scene, double maxPatchArea) {
    MeshingOptions options;
    options.maxPatchArea = maxPatchArea;
    return meshScene(scene, options);
}

void solveTo(Solver& solver, double residual, std::size_t maxSteps) {
    for (std::size_t k = 0; k < maxSteps && solver.lastStats().residual > residual; ++k) solver.step();
    REQUIRE(solver.lastStats().residual <= residual);
}

/// Area-weighted mean radiosity (first band) of each surface over the mesh's patches.
std::vector<double> surfaceMeans(const PatchMesh& mesh, const std::vector<Rgb>& B) {
    std::vector<double> means;
    for (std::size_t s = 0; s + 1 < mesh.surfaceFirstPatch.size(); ++s) {
        double power = 0, area = 0;
        for (std::size_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
            power += mesh.patches[i].area * B[i].x;
            area += mesh.patches[i].area;
        }
        means.push_back(power / area);
    }
    return means;
}

} // namespace

TEST_SUITE("importance") {

TEST_CASE("the Cornell box's home view is the published camera: field of view 2 atan(12.5 / 35)") {
    const View view = homeView(makeCornellBox());
    CHECK(view.verticalFov == doctest::Approx(2 * std::atan(12.5 / 35)).scale(0).epsilon(1e-12));
    CHECK(view.verticalFov == doctest::Approx(0.68605).scale(0).epsilon(1e-5));
    CHECK(view.eye.z == doctest::Approx(-0.8).scale(0).epsilon(1e-12));
}

TEST_CASE("importance refines on every built-in scene from its home view") {
    for (const std::string& name : builtinSceneNames()) {
        CAPTURE(name);
        const Scene scene = makeBuiltinScene(name);
        const PatchMesh mesh = meshAt(scene, 0.05);
        ImportanceSolver solver(scene, mesh, SolverOptions{}, nullptr);
        // Some front face is in view: eye rays landed, so importance is positive somewhere.
        const auto& emitted = solver.emittedImportance();
        CHECK(std::any_of(emitted.begin(), emitted.end(), [](double r) { return r > 0; }));
        for (int k = 0; k < 4; ++k) solver.step();
        const std::size_t roots = solver.elements().roots().size();
        const std::size_t leaves = solver.elements().leaves().size();
        MESSAGE(name, ": ", roots, " roots, ", leaves, " leaves");
        CHECK(leaves > roots);
    }
}

TEST_CASE("a view that sees no surface's front is an error, and setView keeps the previous view") {
    const Scene cube = makeUnitCube();
    const PatchMesh mesh = meshAt(cube, 0.05);
    SolverOptions outside;
    // Outside the closed cube, looking at it: every eye ray hits a wall's back.
    outside.view = View{{0.5, 0.5, -3.0}, {0.5, 0.5, 0.5}, {0, 1, 0}, 0.6, 1.0};
    CHECK_THROWS_AS(ImportanceSolver(cube, mesh, outside, nullptr), RadiantError);
    // Looking away into empty space: no hit at all.
    outside.view = View{{0.5, 0.5, -3.0}, {0.5, 0.5, -6.0}, {0, 1, 0}, 0.6, 1.0};
    CHECK_THROWS_AS(ImportanceSolver(cube, mesh, outside, nullptr), RadiantError);

    ImportanceSolver solver(cube, mesh, SolverOptions{}, nullptr);
    for (int k = 0; k < 3; ++k) solver.step();
    const std::vector<double> before = solver.emittedImportance();
    CHECK_THROWS_AS(solver.setView(cube, *outside.view), RadiantError);
    CHECK(solver.emittedImportance() == before);
}

TEST_CASE("setView moves the refinement to what the new camera sees") {
    const Scene cube = makeUnitCube();
    const PatchMesh mesh = meshAt(cube, 0.05);
    const std::size_t floor = cube.findSurface("floor");
    // From just below the ceiling looking down at the floor, then from near wall +z across at wall -z.
    const View atFloor{{0.5, 0.9, 0.5}, {0.5, 0.0, 0.5}, {0, 0, 1}, 1.0, 1.0};
    const View atWall{{0.5, 0.5, 0.9}, {0.5, 0.5, 0.0}, {0, 1, 0}, 0.3, 1.0};
    SolverOptions options;
    options.view = atFloor;
    ImportanceSolver solver(cube, mesh, options, nullptr);
    const auto leavesOn = [&](std::size_t surface) {
        std::size_t count = 0;
        for (const ElementIndex e : solver.elements().leaves()) count += solver.elements().surface(e) == surface;
        return count;
    };
    for (int k = 0; k < 4; ++k) solver.step();
    const std::size_t farWall = cube.findSurface("wall -z");
    REQUIRE(farWall != Scene::npos);
    const std::size_t floorBefore = leavesOn(floor), wallBefore = leavesOn(farWall);
    solver.setView(cube, atWall);
    for (int k = 0; k < 4; ++k) solver.step();
    MESSAGE("floor ", floorBefore, " -> ", leavesOn(floor), " leaves; far wall ", wallBefore, " -> ", leavesOn(farWall));
    CHECK(leavesOn(farWall) > wallBefore);
    CHECK(leavesOn(floor) >= floorBefore);  // links and elements stay: the re-solve starts from them
}

TEST_CASE("unit cube, rho 0.5, 0.01 m^2: importance from the home view agrees with Gauss-Seidel") {
    const Scene cube = makeUnitCube();
    const PatchMesh mesh = meshAt(cube, 0.01);
    auto reference = makeSolver(SolverMethod::GaussSeidel, cube, mesh);
    solveTo(*reference, 1e-9, 1000);
    ImportanceSolver solver(cube, mesh, SolverOptions{}, nullptr);
    solveTo(solver, 1e-6, 1000);
    const std::vector<double> expected = surfaceMeans(mesh, reference->solution());
    const std::vector<double> got = surfaceMeans(mesh, solver.solution());
    for (std::size_t s = 0; s < cube.surfaces.size(); ++s) {
        CAPTURE(cube.surfaces[s].name);
        MESSAGE(cube.surfaces[s].name, ": importance ", got[s], ", Gauss-Seidel ", expected[s]);
        CHECK(got[s] == doctest::Approx(expected[s]).scale(0).epsilon(0.02));
    }
}

TEST_CASE("the solver thread takes the lab's camera: a blind view is an error shown, a good one re-solves") {
    using namespace radiant::app;
    auto cube = std::make_shared<const Scene>(makeUnitCube());
    SolverThread thread;
    thread.send(command::LoadScene{cube, MeshingOptions{0.05}});
    thread.send(command::SetMethod{SolverMethod::Importance});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    REQUIRE(thread.snapshot()->error.empty());
    const std::size_t builds = thread.snapshot()->solverBuilds;
    // Outside the closed cube: every eye ray hits a wall's back.
    thread.send(command::SetView{View{{0.5, 0.5, -3.0}, {0.5, 0.5, 0.5}, {0, 1, 0}, 0.6, 1.6}});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->error.find("sees no surface's front") != std::string::npos);
    // Inside, looking at the floor: accepted, the same solver refines for it and runs to the tolerance.
    thread.send(command::SetView{View{{0.5, 0.9, 0.5}, {0.5, 0.0, 0.5}, {0, 0, 1}, 1.0, 1.6}});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK(snapshot->solverBuilds == builds);
    CHECK(snapshot->stats.residual < snapshot->tolerance);
}

} // TEST_SUITE
