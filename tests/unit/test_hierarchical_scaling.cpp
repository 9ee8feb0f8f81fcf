// Hierarchical radiosity scaled by element count (hierarchicalSetupForElements): the leaves reach
// the requested resolution and the links grow linearly with them, not quadratically. These are
// properties of the algorithm (Hanrahan, Salzman, Aupperle 1991, Section 4), not closed forms; the
// physics of the same solver is tested against closed forms in test_hierarchical.cpp.
#include <doctest/doctest.h>

#include <cmath>

#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/HierarchicalSolver.h"

using namespace radiant;

namespace {

struct Scaled {
    std::size_t leaves = 0, links = 0;
    double largestLeaf = 0;
    std::size_t steps = 0;
};

Scaled solveFor(const Scene& scene, const PatchMesh& mesh, std::size_t elements) {
    const HierarchicalSetup setup = hierarchicalSetupForElements(scene, elements);
    HierarchicalSolver solver(scene, mesh, setup.options, nullptr, setup.refinement);
    Scaled result;
    for (result.steps = 1; result.steps <= 60; ++result.steps)
        if (solver.step().residual <= 1e-3) break;
    const ElementTree& tree = solver.elements();
    for (const ElementIndex e : tree.leaves()) result.largestLeaf = std::max(result.largestLeaf, tree.area(e));
    result.leaves = tree.leafCount();
    result.links = solver.links().size();
    return result;
}

} // namespace

TEST_SUITE("hierarchical") {

TEST_CASE("hierarchical scaling: 4x the elements, at most 4x the links") {
    const Scene scene = makeCornellBox();
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.05;
    const PatchMesh mesh = meshScene(scene, meshing);
    const Scaled coarse = solveFor(scene, mesh, 2000);
    const Scaled fine = solveFor(scene, mesh, 8000);
    CHECK(coarse.steps <= 60);
    CHECK(fine.steps <= 60);
    // Every leaf at least as fine as asked (twice the mean area, see hierarchicalSetupForElements).
    CHECK(coarse.largestLeaf <= 2 * scene.totalArea() / 2000);
    CHECK(fine.largestLeaf <= 2 * scene.totalArea() / 8000);
    CHECK(fine.leaves > 3 * coarse.leaves);
    const double coarsePerLeaf = static_cast<double>(coarse.links) / static_cast<double>(coarse.leaves);
    const double finePerLeaf = static_cast<double>(fine.links) / static_cast<double>(fine.leaves);
    // Linear memory: links per leaf do not grow with the leaves (a fixed threshold, as before this
    // scaling, took them from 17 to 105 between 10k and 236k elements).
    CHECK(finePerLeaf <= 1.05 * coarsePerLeaf);
    MESSAGE(coarse.leaves << " leaves, " << coarsePerLeaf << " links per leaf; " << fine.leaves << " leaves, "
                          << finePerLeaf << " links per leaf");
}

} // TEST_SUITE
