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
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/reference/PathTracer.h"
#include "radiometry/reference/ReferencePoint.h"
#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/scene/View.h"
#include "radiometry/solver/ImportanceSolver.h"
#include "radiometry/solver/SolveDefaults.h"
#include "tests/support/Relative.h"

using namespace radiant;

namespace {

PatchMesh meshForImportance(const Scene& scene, double maxPatchArea) {
    MeshingOptions options;
    options.maxPatchArea = maxPatchArea;
    return meshScene(scene, options);
}

void solveImportanceTo(Solver& solver, double residual, std::size_t maxSteps) {
    for (std::size_t k = 0; k < maxSteps && solver.lastStats().residual > residual; ++k) solver.step();
    REQUIRE(solver.lastStats().residual <= residual);
}

/// Area-weighted mean radiosity (first band) of each surface over the mesh's patches.
std::vector<double> importanceSurfaceMeans(const PatchMesh& mesh, const std::vector<Rgb>& B) {
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
        const PatchMesh mesh = meshForImportance(scene, 0.05);
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
    const PatchMesh mesh = meshForImportance(cube, 0.05);
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
    const PatchMesh mesh = meshForImportance(cube, 0.05);
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
    const PatchMesh mesh = meshForImportance(cube, 0.01);
    auto reference = makeSolver(SolverMethod::GaussSeidel, cube, mesh);
    solveImportanceTo(*reference, 1e-9, 1000);
    ImportanceSolver solver(cube, mesh, SolverOptions{}, nullptr);
    solveImportanceTo(solver, 1e-6, 1000);
    const std::vector<double> expected = importanceSurfaceMeans(mesh, reference->solution());
    const std::vector<double> got = importanceSurfaceMeans(mesh, solver.solution());
    for (std::size_t s = 0; s < cube.surfaces.size(); ++s) {
        CAPTURE(cube.surfaces[s].name);
        MESSAGE(cube.surfaces[s].name, ": importance ", got[s], ", Gauss-Seidel ", expected[s]);
        CHECK(got[s] == doctest::Approx(expected[s]).scale(0).epsilon(0.02));
    }
}

// ctest-case-labels: heavy
TEST_CASE("Cornell box at the defaults: the short block's sides as the probe reads them agree with the path tracer") {
    // The side facing the camera sees, up close, the floor strip in front of the block: in the block's
    // penumbra and below the camera's view, so importance leaves it coarse, and its patches must take
    // their visibility from rays of their own. That side read 3.4% dark against the tracer (4% in the
    // blue band) when the patches kept their links' few-ray shares, or 3.3% bright with seed 2, whose
    // solve reached the tolerance before the rows were built. Now within 2% in every band, seeds 1 and 2
    // (measured: within 0.8%): the mesh's own share at these points is +0.03% to +0.71% (converged
    // Gauss-Seidel against the tracer, `radiant bench --only accuracy`), the tracer's standard error
    // at most 0.3%.
    const Scene scene = makeCornellBox();
    const PatchMesh mesh = meshForImportance(scene, kSolveDefaults.maxPatchArea);
    const RayCaster rays(scene);
    const Probe probe(scene, mesh, &rays);
    const PathTracer tracer(scene, rays);
    const Surface& block = scene.surfaces.at(scene.findSurface("short block"));
    std::vector<ReferencePoint> sides;
    std::vector<ReferenceEstimate> references;
    for (std::size_t side = 1; side <= 4; ++side) {
        const Face& face = block.faces.at(side);
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& v : face.vertices) centre += v / static_cast<double>(face.vertices.size());
        sides.push_back(locateReferencePoint(scene, centre, face.normal));
        ReferenceRun run(tracer, sides.back(), {100 + side, 2, 4096});
        ReferenceStop stop;
        stop.relativeStandardError = 0.003;
        stop.samples = 8'000'000;  // a ceiling: a run that needs more fails the precision check below
        references.push_back(run.runUntil(stop));
        REQUIRE(references.back().relativeStandardError() <= 0.003);
    }
    for (const std::uint64_t seed : {1u, 2u}) {
        SolverOptions options;
        options.seed = seed;
        ImportanceSolver solver(scene, mesh, options, nullptr);
        solveImportanceTo(solver, kSolveDefaults.tolerance, 200);
        for (std::size_t k = 0; k < sides.size(); ++k) {
            const Rgb got = probe.measure(sides[k].point, sides[k].normal, solver.solution()).radiosity.value();
            const Rgb expected = references[k].radiosity.value();
            for (int band = 0; band < 3; ++band) {
                CAPTURE(seed);
                CAPTURE(k + 1);
                CAPTURE(band);
                CHECK(got[band] == test::relativeTo(expected[band], 0.02));
            }
        }
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
