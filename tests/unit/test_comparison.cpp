// ctest-labels: threads
// Comparison mode (issue #16 item 5): a second solver thread takes every command the first does,
// except what makes it B (its method, its meshing), and both reach the furnace's closed form
// B = E / (1 - rho); the difference of two solutions maps each patch of the finer mesh to the patch
// of the coarser one containing its centre.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "app/solver/Comparison.h"
#include "app/solver/LiveSolve.h"
#include "app/solver/SolveHistory.h"
#include "app/solver/SolutionDifference.h"
#include "app/solver/SolverThread.h"
#include "radiometry/mesh/PatchLocator.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// |a - b| / |b|: doctest's epsilon is absolute below 1.
double relativeError(double a, double b) { return std::abs(a - b) / std::abs(b); }

/// A snapshot that has stepped once, with the given per-patch radiosity on `mesh`.
Snapshot steppedSnapshot(std::shared_ptr<const Scene> scene, std::shared_ptr<const PatchMesh> mesh,
                         std::vector<Rgb> radiosity, std::uint64_t generation) {
    Snapshot s;
    s.scene = std::move(scene);
    s.mesh = std::move(mesh);
    s.radiosity = std::move(radiosity);
    s.generation = generation;
    SolveHistoryBuilder history;
    IterationStats step;
    step.iteration = 1;
    history.append(step);
    s.history = history.snapshot();
    return s;
}

} // namespace

TEST_SUITE("comparison") {

TEST_CASE("B takes every command but its own method, with its meshing scaled and the focus moved to its mesh") {
    ComparisonSettings settings;
    settings.method = SolverMethod::Progressive;
    settings.patchAreaScale = 0.25;
    CHECK_FALSE(commandForSecond(command::SetMethod{SolverMethod::Jacobi}, settings, 7));
    const std::optional<SolverCommand> remesh = commandForSecond(command::Remesh{MeshingOptions{0.04}}, settings, 7);
    REQUIRE(remesh);
    REQUIRE(std::holds_alternative<command::Remesh>(*remesh));
    CHECK(std::get<command::Remesh>(*remesh).meshing.maxPatchArea == doctest::Approx(0.01).scale(0));
    const std::optional<SolverCommand> load = commandForSecond(command::LoadScene{nullptr, MeshingOptions{0.1}}, settings, 7);
    REQUIRE(load);
    CHECK(std::get<command::LoadScene>(*load).meshing.maxPatchArea == doctest::Approx(0.025).scale(0));
    command::FocusedPoint at;
    at.meshGeneration = 3;
    const std::optional<SolverCommand> focus = commandForSecond(command::FocusPoint{at}, settings, 7);
    REQUIRE(focus);
    CHECK(std::get<command::FocusPoint>(*focus).at->meshGeneration == 7);
    for (const SolverCommand& same : {SolverCommand{command::Run{}}, SolverCommand{command::Pause{}},
                                      SolverCommand{command::Reset{}}, SolverCommand{command::Step{3}},
                                      SolverCommand{command::SetTolerance{1e-6}}, SolverCommand{command::ResetMaterials{}}}) {
        const std::optional<SolverCommand> forB = commandForSecond(same, settings, 7);
        REQUIRE(forB);
        CHECK(forB->index() == same.index());
    }
}

TEST_CASE("Jacobi and Gauss-Seidel on two threads, B on a mesh twice as fine, both reach E / (1 - rho) in the furnace") {
    auto furnace = std::make_shared<const Scene>(loadScene("furnace").scene);
    const Material& wall = furnace->materials.at(0);
    SolverThread first;
    LiveSolve live(first);
    live.send(command::SetMethod{SolverMethod::Jacobi});
    live.send(command::LoadScene{furnace, MeshingOptions{0.1}});
    live.send(command::SetTolerance{1e-8});
    first.waitUntilIdle();
    live.refresh();
    REQUIRE(live.snapshot().mesh);

    ComparisonSettings settings;
    settings.method = SolverMethod::GaussSeidel;
    settings.patchAreaScale = 0.25;
    live.setComparison(settings);
    live.compare(true);
    REQUIRE(live.comparing());
    live.send(command::Run{});
    first.waitUntilIdle();
    live.second->waitUntilIdle();
    live.refresh();
    const Snapshot& a = live.snapshot();
    const Snapshot& b = *live.secondCurrent;
    REQUIRE(a.error.empty());
    REQUIRE(b.error.empty());
    CHECK(a.method == SolverMethod::Jacobi);
    CHECK(b.method == SolverMethod::GaussSeidel);
    CHECK(b.tolerance == a.tolerance);
    REQUIRE(a.mesh);
    REQUIRE(b.mesh);
    CHECK(b.meshing.maxPatchArea == doctest::Approx(a.meshing.maxPatchArea / 4).scale(0));
    CHECK(b.mesh->size() >= 3 * a.mesh->size());
    CHECK(a.stats.residual < a.tolerance);
    CHECK(b.stats.residual < b.tolerance);
    // The lecture's point: Gauss-Seidel needs fewer sweeps than Jacobi.
    CHECK(b.stats.iteration < a.stats.iteration);

    // Meshed form factors sum to 1 per row only to quadrature accuracy: the closed form within 1%.
    for (const Snapshot* s : {&a, &b})
        for (const Rgb& radiosity : s->radiosity)
            for (int band = 0; band < 3; ++band)
                CHECK(relativeError(radiosity[band], wall.exitance.value()[band] / (1 - wall.reflectance[band])) < 0.01);

    SolutionDifferencer differencer;
    const SolutionDifference& d = differencer.update(a, b);
    REQUIRE(d.mesh);
    CHECK_FALSE(d.onFirst);  // B's mesh is the finer
    CHECK(d.mesh == b.mesh);
    CHECK(d.relative.size() == b.mesh->size());
    CHECK(d.maxRelative < 0.02);
    CHECK(d.meanRelative <= d.maxRelative);

    live.compare(false);
    CHECK_FALSE(live.comparing());
    CHECK_FALSE(live.secondCurrent);
}

TEST_CASE("turned on with B the same as A, B becomes A's partner in the lecture: Jacobi against Gauss-Seidel") {
    SolverThread first;
    LiveSolve live(first);
    live.send(command::SetMethod{SolverMethod::GaussSeidel});
    live.compare(true);  // the default B is Gauss-Seidel too
    CHECK(live.comparison().method == SolverMethod::Jacobi);
    live.compare(false);
    live.send(command::SetMethod{SolverMethod::Hierarchical});
    ComparisonSettings settings;
    settings.method = SolverMethod::Hierarchical;
    settings.patchAreaScale = 0.25;  // one method at two meshings: kept
    live.setComparison(settings);
    live.compare(true);
    CHECK(live.comparison().method == SolverMethod::Hierarchical);
}

TEST_CASE("each patch of the finer mesh corresponds to the coarser patch containing its centre") {
    const Scene box = loadScene("cornell-box").scene;
    const PatchMesh coarse = meshScene(box, {0.04});
    const PatchMesh fine = meshScene(box, {0.01});
    const std::vector<std::size_t> coarseOf = SolutionDifferencer::correspondence(fine, coarse);
    REQUIRE(coarseOf.size() == fine.size());
    for (std::size_t p = 0; p < fine.size(); ++p) {
        const Patch& f = fine.patches[p];
        const Patch& c = coarse.patches.at(coarseOf[p]);
        CHECK(c.surface == f.surface);
        CHECK(c.face == f.face);
        CHECK(distanceOutsidePatch(coarse, coarseOf[p], f.centroid) <= 1e-9);
    }
    // Alike meshes: the identity.
    const PatchMesh again = meshScene(box, {0.04});
    const std::vector<std::size_t> same = SolutionDifferencer::correspondence(coarse, again);
    for (std::size_t p = 0; p < same.size(); ++p) CHECK(same[p] == p);
}

TEST_CASE("the relative difference of two radiosities is of their band totals, 0 where both are dark") {
    CHECK(relativeDifference(Rgb(1.0), Rgb(1.0)) == 0.0);
    CHECK(relativeDifference(Rgb(0.0), Rgb(0.0)) == 0.0);
    CHECK(relativeDifference(Rgb(2.0, 0.0, 0.0), Rgb(1.0, 0.0, 0.0)) == doctest::Approx(0.5).scale(0));
    CHECK(relativeDifference(Rgb(0.0), Rgb(3.0)) == doctest::Approx(1.0).scale(0));
    // A floor above both: the difference relative to it.
    CHECK(relativeDifference(Rgb(0.0), Rgb(1e-6), 1e-2) == doctest::Approx(3e-4).scale(0));
    CHECK(relativeDifference(Rgb(1.0), Rgb(0.5), 1e-2) == doctest::Approx(0.5).scale(0));
}

TEST_CASE("a patch neither solution lights counts its stray light against 1% of the mean radiosity, not as 100%") {
    // The Cornell box at 0.001 m^2, progressive against Gauss-Seidel, showed "largest 100%": floor
    // patches under a block, 0 in one solution and 1.7e-6 to 9.7e-5 W/m^2 (R+G+B) in the other. Here the
    // same on a hand-made pair of solutions whose measure has a closed form: every patch B = 1 W/m^2
    // per band (3 in total) on both sides but for patch `dark`, 0 in A and 1e-5 per band in B, and
    // patch `lit`, 10% brighter in B.
    auto scene = std::make_shared<const Scene>(loadScene("cornell-box").scene);
    auto mesh = std::make_shared<const PatchMesh>(meshScene(*scene, {0.04}));
    const std::size_t n = mesh->size();
    REQUIRE(n > 10);
    const std::size_t dark = 3, lit = 7;
    std::vector<Rgb> a(n, Rgb(1.0)), b(n, Rgb(1.0));
    a[dark] = Rgb(0.0);
    b[dark] = Rgb(1e-5);
    b[lit] = Rgb(1.1);
    double area = 0, power = 0;  // both sides' mean of the R+G+B totals, area-weighted
    for (std::size_t p = 0; p < n; ++p) {
        area += mesh->patches[p].area;
        power += 0.5 * ((a[p].x + a[p].y + a[p].z) + (b[p].x + b[p].y + b[p].z)) * mesh->patches[p].area;
    }
    const double floor = 0.01 * power / area;  // about 0.03 W/m^2
    SolutionDifferencer differencer;
    const SolutionDifference& d = differencer.update(steppedSnapshot(scene, mesh, a, 1), steppedSnapshot(scene, mesh, b, 1));
    REQUIRE(d.mesh);
    CHECK(d.darkFloor == doctest::Approx(floor).epsilon(1e-12));
    CHECK(d.darkPatches == 1);
    // Before the floor, patch `dark` read |0 - 3e-5| / 3e-5 = 1, and so did the largest.
    CHECK(d.relative[dark] == doctest::Approx(3e-5 / floor).epsilon(1e-12));
    CHECK(d.relative[dark] < 1e-2);
    // A lit patch's difference is its own: 0.3 / 3.3.
    CHECK(d.relative[lit] == doctest::Approx(0.3 / 3.3).epsilon(1e-12));
    CHECK(d.maxRelative == d.relative[lit]);
    CHECK(d.largestPatch == lit);
    for (std::size_t p = 0; p < n; ++p)
        if (p != dark && p != lit) CHECK(d.relative[p] == 0.0);
}

} // TEST_SUITE
