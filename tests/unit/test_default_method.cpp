// ctest-labels: threads
// The default method fits the scene (#20 item 4): progressive refinement while the mesh is small,
// hierarchical beyond, never a form-factor matrix, the same choice in `solve`, `probe`, `render` and the lab, each saying why; an explicit
// method still wins; the lab's refusal names its meshing slider, the command line's its flag.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/solver/SolverThread.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"
#include "tests/support/RunRadiant.h"
#include "tests/support/Common.h"

using namespace radiant;
using namespace radiant::app;
namespace fs = std::filesystem;

namespace {

using radiant::test::contains;

using Run = test::CommandRun;
using test::runRadiant;

/// The unit cube's largest patch area for about `patches` patches (its six square metres).
double areaFor(std::size_t patches) { return 6.0 / static_cast<double>(patches); }

} // namespace

TEST_SUITE("default method") {

TEST_CASE("the Cornell box gets progressive refinement at the default meshing, and says why") {
    const Scene box = makeCornellBox();
    const MeshingOptions meshing{kSolveDefaults.maxPatchArea};
    const std::size_t patches = estimatePatchCount(box, meshing);
    REQUIRE(patches == 2248);  // 2,805 at 10 cm^2 before the floor before the blocks was meshed finer (besideContactAreaShare); 2,170 before the floor was cut along their footprints (ContactCuts.h)
    const MethodChoice choice = chooseDefaultMethod(box, meshing);
    CHECK(choice.method == SolverMethod::Progressive);
    CHECK(choice.method == kSolveDefaults.method);
    INFO(choice.reason);
    CHECK(contains(choice.reason, "2,248 patches: progressive refinement, "));
    CHECK(contains(choice.reason, "hierarchical above 3,000 patches"));
}

TEST_CASE("above the threshold the default is hierarchical, and the reason says why") {
    CHECK(chooseDefaultMethod(kProgressiveMaxPatches).method == SolverMethod::Progressive);
    CHECK(chooseDefaultMethod(kProgressiveMaxPatches + 1).method == SolverMethod::Hierarchical);

    // The classroom of the issue: 26,264 patches, whose Gauss-Seidel matrix was refused.
    const MethodChoice classroom = chooseDefaultMethod(26'264);
    CHECK(classroom.method == SolverMethod::Hierarchical);
    INFO(classroom.reason);
    CHECK(contains(classroom.reason, "26,264 patches: progressive refinement's time grows faster"));
    CHECK(contains(classroom.reason, "hierarchical above 3,000 patches"));
}

TEST_CASE("with patch groups the default is progressive refinement over them, however many") {
    for (const std::size_t groups : {std::size_t{75}, kProgressiveMaxPatches, kProgressiveMaxPatches + 1, std::size_t{26'264}}) {
        const MethodChoice choice = chooseDefaultMethodForGroups(groups, 4 * groups);
        CHECK(choice.method == SolverMethod::Progressive);  // hierarchical takes no groups
        CHECK_FALSE(methodInfo(choice.method).traits.formFactorMatrix);
        INFO(choice.reason);
        CHECK(contains(choice.reason, "progressive refinement over the groups"));
        CHECK(contains(choice.reason, "takes no groups"));
    }
    CHECK(contains(chooseDefaultMethodForGroups(75, 3103).reason, "3,103 patches in 75 groups: "));
}

TEST_CASE("no default method builds a form-factor matrix, however large the mesh") {
    for (const std::size_t patches : {std::size_t{24}, kProgressiveMaxPatches, std::size_t{26'264}, std::size_t{1'000'000}})
        CHECK_FALSE(methodInfo(chooseDefaultMethod(patches).method).traits.formFactorMatrix);
}

TEST_CASE("the scene's choice follows the patch count meshing will make") {
    const Scene cube = makeUnitCube();
    for (const double area : {0.25, areaFor(kProgressiveMaxPatches * 9 / 10), areaFor(kProgressiveMaxPatches * 2)}) {
        const MeshingOptions meshing{area};
        const std::size_t patches = meshScene(cube, meshing).size();
        CHECK(chooseDefaultMethod(cube, meshing).method == chooseDefaultMethod(patches).method);
        CHECK(chooseDefaultMethod(cube, meshing).method ==
              (patches > kProgressiveMaxPatches ? SolverMethod::Hierarchical : SolverMethod::Progressive));
    }
}

TEST_CASE("radiant solve without --method picks by size and says so, --method still wins and is still refused") {
    // ~20,000 patches: a Gauss-Seidel matrix would need more than the 4 GB budget.
    const double area = areaFor(20'000);
    REQUIRE(formFactorMatrixPeakBytes(estimatePatchCount(makeUnitCube(), {area})) > SolverOptions{}.matrixBudgetBytes);
    const std::string areaText = std::to_string(area);
    // One step is enough to show the method ran (hierarchical links are made in the first).
    const Run chosen = runRadiant("solve unit-cube --max-patch-area " + areaText + " --max-iterations 1 --json -");
    INFO(chosen.err);
    REQUIRE(chosen.status == 0);
    CHECK(contains(chosen.err, "radiant: method: hierarchical ("));
    CHECK(contains(chosen.err, "hierarchical above 3,000 patches"));
    const nlohmann::json report = nlohmann::json::parse(chosen.out);
    CHECK(report["method"] == "hierarchical");
    CHECK(contains(report["method_reason"].get<std::string>(), "patches: progressive refinement's time grows"));

    const Run named = runRadiant("solve unit-cube --method gauss-seidel --max-patch-area " + areaText);
    INFO(named.err);
    CHECK(named.status == 2);
    CHECK(contains(named.err, "unit-cube: form-factor matrix: a form-factor matrix for "));
    CHECK(contains(named.err, "or a larger --max-patch-area"));  // the command line names its flag
    CHECK(!contains(named.err, "radiant: method:"));              // nothing was chosen

    const Run small = runRadiant("solve unit-cube --max-patch-area 0.25 --json -");
    INFO(small.err);
    REQUIRE(small.status == 0);
    CHECK(contains(small.err, "radiant: method: progressive (24 patches: "));
    CHECK(nlohmann::json::parse(small.out)["method"] == "progressive");
    const Run jacobi = runRadiant("solve unit-cube --method jacobi --max-patch-area 0.25 --json -");
    REQUIRE(jacobi.status == 0);
    CHECK(nlohmann::json::parse(jacobi.out)["method_reason"] == "given by --method");
}

TEST_CASE("radiant probe chooses the same way and reports it in its JSON") {
    const Run run = runRadiant("probe unit-cube --point 0.5,0,0.5 --normal 0,1,0 --max-patch-area 0.25");
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK(contains(run.err, "radiant: method: progressive (24 patches: "));
    const nlohmann::json out = nlohmann::json::parse(run.out);
    CHECK(out["method"] == "progressive");
    CHECK(contains(out["method_reason"].get<std::string>(), "24 patches"));
}

TEST_CASE("the lab opens a scene too large for progressive refinement with hierarchical and no error, and says why") {
    // No matrix method may be built: computing one for this many patches is what the default avoids.
    std::atomic<int> matrixBuilds{0};
    const SolverFactory factory = [&](SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                      const SolverOptions& options, Progress* progress) -> std::unique_ptr<Solver> {
        if (methodInfo(method).traits.formFactorMatrix) {
            ++matrixBuilds;
            throw RadiantError({"", "test"}, "a matrix method was built for " + std::to_string(mesh.size()) + " patches");
        }
        return makeSolver(method, scene, mesh, options, progress);
    };
    SolverThread thread({}, factory);
    auto cube = std::make_shared<const Scene>(makeUnitCube());
    thread.send(command::LoadScene{cube, MeshingOptions{areaFor(kProgressiveMaxPatches * 3 / 2)}});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    INFO(snapshot->error);
    CHECK(snapshot->error.empty());
    CHECK(matrixBuilds.load() == 0);
    REQUIRE(snapshot->mesh);
    CHECK(snapshot->mesh->size() > kProgressiveMaxPatches);
    CHECK(snapshot->method == SolverMethod::Hierarchical);
    CHECK(snapshot->stats.iteration == 1);
    CHECK(contains(snapshot->methodReason, "patches: progressive refinement's time grows"));

    // Coarser meshing (the slider) brings the small mesh's method back while none was picked.
    thread.send(command::Remesh{MeshingOptions{0.25}});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->method == SolverMethod::Progressive);
    CHECK(contains(snapshot->methodReason, "24 patches: progressive refinement, "));
}

TEST_CASE("in the lab a picked method stays across re-meshing, and its refusal names the meshing slider") {
    SolverOptions options;
    options.matrixBudgetBytes = 1e6;  // a small budget stands for a large scene: ~260 patches fit
    SolverThread thread(options);
    auto cube = std::make_shared<const Scene>(makeUnitCube());
    thread.send(command::LoadScene{cube, MeshingOptions{0.25}});
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK(snapshot->method == SolverMethod::Jacobi);
    CHECK(snapshot->methodReason.empty());  // picked, not chosen

    thread.send(command::Remesh{MeshingOptions{areaFor(600)}});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->method == SolverMethod::Jacobi);
    INFO(snapshot->error);
    CHECK(contains(snapshot->error, "the budget is"));
    CHECK(contains(snapshot->error, "the Scene panel's meshing slider"));
    CHECK(!contains(snapshot->error, "--max-patch-area"));

    // Opening a scene never ends in that refusal: a pick whose matrix cannot hold it gives way.
    thread.send(command::LoadScene{cube, MeshingOptions{areaFor(600)}});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK(snapshot->method == kSolveDefaults.method);
    CHECK(contains(snapshot->methodReason, "patches: progressive refinement, "));
}

} // TEST_SUITE

TEST_SUITE("default method") {

TEST_CASE("a Blender-style room file gets its method by size: hierarchical over 3,000 patches, progressive over its groups at the lab's opening area") {
    // tests/data/grouping/sphere_room.gltf (make_sphere_room.py): a 57 m^2 room around a UV sphere.
    const std::string room = std::string("'") + RADIANT_TEST_DATA_DIR + "/grouping/sphere_room.gltf'";
    const Run fine = runRadiant("solve " + room + " --max-patch-area 0.01 --max-iterations 1 --json -");
    INFO(fine.err);
    REQUIRE(fine.status == 0);
    const nlohmann::json fineReport = nlohmann::json::parse(fine.out);
    CHECK(fineReport["method"] == "hierarchical");
    CHECK(fineReport["patches"].get<int>() > 3000);
    CHECK(contains(fine.err, "radiant: method: hierarchical ("));
    CHECK(contains(fine.err, "hierarchical above 3,000 patches"));

    // At the lab's opening area for this room the sphere's patches are grouped and progressive
    // refinement solves the groups.
    const Run coarse = runRadiant("solve " + room + " --max-patch-area 0.025 --max-iterations 1 --json -");
    INFO(coarse.err);
    REQUIRE(coarse.status == 0);
    const nlohmann::json coarseReport = nlohmann::json::parse(coarse.out);
    CHECK(coarseReport["method"] == "progressive");
    CHECK(coarseReport["grouped"] == true);
    CHECK(coarseReport["unknowns"].get<int>() < coarseReport["patches"].get<int>());
    CHECK(contains(coarse.err, "radiant: method: progressive ("));
}

} // TEST_SUITE
