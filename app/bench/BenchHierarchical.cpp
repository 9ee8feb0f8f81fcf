// Hierarchical radiosity scaled by element count on the Cornell box (issue #5): time to residual
// 1e-3 with the refinement tied to the element size (hierarchicalSetupForElements), links and bytes
// per leaf, how many leaves gather over links of their own, and the accuracy (furnace closed form,
// Gauss-Seidel surface means), beside the targets.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <string>
#include <vector>

#include "app/bench/BenchTable.h"
#include "app/bench/HierarchicalAccuracy.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/solver/HierarchicalSolver.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app {

namespace {

struct Target {
    std::size_t elements;
    double seconds;  ///< issue #5: wall time to residual 1e-3, set-up included
};

} // namespace

BenchTable benchHierarchical(const BenchOptions& options) {
    BenchTable table{"Hierarchical radiosity by element count (Cornell box, to residual 1e-3)",
                     {"elements asked", "leaves", "leaves with own links", "links / leaf", "bytes / leaf",
                      "rays / link", "steps", "wall (s)", "CPU (s)", "CPU us / link", "target (s)", "verdict",
                      "vs Gauss-Seidel", "furnace rms", "furnace worst leaf"},
                     {},
                     {}};
    const CornellBoxAsShown box = cornellBoxAsShown();
    const Scene& scene = box.scene;
    const PatchMesh& mesh = box.mesh;
    const GaussSeidelReference& reference = cornellGaussSeidelReference(options.quick);
    const std::vector<Rgb>& referenceMeans = reference.surfaceMeans;
    const std::vector<Target> targets = options.quick
                                            ? std::vector<Target>{{10'000, 0.3}, {40'000, 0}}
                                            : std::vector<Target>{{10'000, 0.3}, {100'000, 0}, {1'000'000, 60}};
    double firstLinksPerLeaf = 0, firstBytesPerLeaf = 0;
    std::size_t lastLinked = 0, lastLinks = 0;
    double lastCpuPerLink = 0, lastRaysPerLink = 0;
    for (const Target& target : targets) {
        const auto wallStart = std::chrono::steady_clock::now();
        const std::clock_t cpuStart = std::clock();
        const HierarchicalSetup setup = hierarchicalSetupForElements(scene, target.elements);
        HierarchicalSolver solver(scene, mesh, setup.options, nullptr, setup.refinement);
        std::size_t steps = 0;
        while (steps < 200 && solver.step().residual > 1e-3) ++steps;
        ++steps;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
        const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        const auto leaves = static_cast<double>(solver.elements().leafCount());
        const auto links = static_cast<double>(solver.links().size());
        const double linksPerLeaf = links / leaves;
        const double bytesPerLeaf = static_cast<double>(solver.bytes()) / leaves;
        std::vector<bool> receives(solver.elements().size(), false);
        for (const Link& link : solver.links()) receives[link.receiver] = true;
        std::size_t linkedLeaves = 0;
        for (const ElementIndex e : solver.elements().leaves()) linkedLeaves += receives[e] ? 1 : 0;
        if (firstLinksPerLeaf == 0) {
            firstLinksPerLeaf = linksPerLeaf;
            firstBytesPerLeaf = bytesPerLeaf;
        }
        lastLinked = linkedLeaves;
        lastLinks = solver.links().size();
        lastCpuPerLink = 1e6 * cpu / links;
        lastRaysPerLink = static_cast<double>(solver.raysCast()) / links;
        const FurnaceError furnace = furnaceError(target.elements);
        table.rows.push_back({std::to_string(target.elements), std::to_string(solver.elements().leafCount()),
                              std::to_string(linkedLeaves) + " (" +
                                  formatNumber(100 * static_cast<double>(linkedLeaves) / leaves, 2) + "%)",
                              formatNumber(linksPerLeaf) + " (" + formatNumber(linksPerLeaf / firstLinksPerLeaf, 2) + "x)",
                              formatNumber(bytesPerLeaf) + " (" + formatNumber(bytesPerLeaf / firstBytesPerLeaf, 2) + "x)",
                              formatNumber(lastRaysPerLink, 2), std::to_string(steps), formatNumber(wall),
                              formatNumber(cpu), formatNumber(lastCpuPerLink, 2),
                              target.seconds > 0 ? formatNumber(target.seconds) : "-",
                              target.seconds > 0 ? timeVerdict(wall, target.seconds) : "-",
                              formatNumber(100 * worstDeviation(solver.elements(), referenceMeans, scene), 2) + "%",
                              formatNumber(100 * furnace.rms, 2) + "%", formatNumber(100 * furnace.worst, 2) + "%"});
    }
    const std::size_t largest = targets.back().elements;
    const std::string linkedVerdict =
        lastLinked >= largest / 2
            ? "met"
            : "missed by " + std::to_string(largest - lastLinked) + " (" + std::to_string(lastLinked) + " leaves with links of their own)";
    table.notes = {
        "One run per row, set-up (tree, root links) included; wall clock on a shared 2-core machine, CPU summed over",
        "both threads. Leaves no larger than a = 2 x scene area A / elements asked; refinement threshold linkEpsilon x",
        "emitted power with linkEpsilon = " + formatNumber(kScaledLinkEpsilon, 2) +
            " x (a / A)^(3/2): the radiosity error a link may leave shrinks like the leaf edge, so more elements",
        "give a better answer (furnace columns); links per leaf then grow like elements^(1/3) at most (ratios to the",
        "first row in brackets). Bytes: elements, links and the solver's per-element arrays (HierarchicalSolver::bytes).",
        "Leaves without links of their own take their irradiance from their ancestors' links (push-pull).",
        std::to_string(largest) + " elements with links of their own (most leaves linked): " + linkedVerdict + ".",
        "  Why: a leaf gets its own link only where a source's light varies across its parent by more than the",
        "  tolerance; mid-wall that takes a tolerance whose near-contact links explode (10k elements with 85% of leaves",
        "  linked measured 1.1M links, 119 per leaf). Largest row: " + std::to_string(lastLinks) + " links, " +
            formatNumber(lastRaysPerLink, 2) + " rays per link (inherited visibility), " + formatNumber(lastCpuPerLink, 2) +
            " CPU us per link.",
        "vs Gauss-Seidel: worst surface-mean difference (any band) from Gauss-Seidel to 1e-9 on " +
            formatNumber(reference.patchArea, 2) + " m^2 patches, whose own meshing error is of that order",
        "(against 0.01, 0.005 and 0.0025 m^2 references the 100k run measured 3.2%, 2.0% and 0.8%).",
        "Furnace: the same setup on the closed furnace, to residual 1e-6, each leaf against E / (1 - rho) (exact",
        "everywhere): area-weighted rms and worst leaf. Issue #14's target: 0.5% rms and 2% worst at 10k and 100k.",
        "Leaves gather through rows of their own form factors to every link of their chain (up to " +
            std::to_string(HierarchicalSolver::kMaxLeavesWithRows) + " leaves; above, ancestors' irradiance is",
        "pushed down as constants, which left corner leaves 14-27% off).",
        "Accuracy at points against the path tracer, by link tolerance, and RenderPark at equal accuracy: the",
        "hierarchical-accuracy table.",
        "Against RenderPark and SPLASH-2 (issue #5) at their element and link counts: the next table.",
    };
    return table;
}

} // namespace radiant::app
