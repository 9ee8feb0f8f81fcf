// Hierarchical radiosity's accuracy at points of the Cornell box against its link tolerance (issue #14),
// and RenderPark's Galerkin hierarchical radiosity at equal accuracy: the figures for it on
// this machine (mean / worst error at points against a path tracer, and wall time) beside Radiant's
// fastest tolerance that is as accurate.
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "app/bench/BenchTable.h"
#include "app/bench/HierarchicalAccuracy.h"
#include "radiometry/solver/HierarchicalSolver.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app {

namespace {

struct Measured {
    double tolerance = 0;
    std::size_t leaves = 0, links = 0, steps = 0;
    double wall = 0;  ///< median, set-up included, to residual kResidual
    PointError error;
};

constexpr double kResidual = 1e-3;

Measured solveAt(const CornellBoxAsShown& box, double tolerance, int repeats, const PointReference& reference) {
    Measured m;
    m.tolerance = tolerance;
    std::vector<double> walls;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        SolverOptions options;
        options.linkEpsilon = tolerance;
        HierarchicalSolver solver(box.scene, box.mesh, options, nullptr);
        std::size_t steps = 0;
        while (steps < 200) {
            ++steps;
            if (solver.step().residual <= kResidual) break;
        }
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (r == 0) {
            m.steps = steps;
            m.leaves = solver.elements().leafCount();
            m.links = solver.links().size();
            m.error = pointError(solver, box, reference);
        }
    }
    m.wall = median(walls);
    return m;
}

struct PublishedPeer {
    const char* setting;
    double mean, worst;  ///< against the path tracer; worst < 0: not stated
    double seconds;
};

} // namespace

BenchTable benchHierarchicalAccuracy(const BenchOptions& options) {
    BenchTable table{"Hierarchical radiosity at points of the Cornell box by link tolerance (to residual 1e-3)",
                     {"link tolerance", "leaves", "links", "steps", "wall median (s)", "mean error", "worst error",
                      "worst at", "target", "verdict"},
                     {},
                     {}};
    const CornellBoxAsShown box = cornellBoxAsShown();
    const PointReference& reference = cornellPointReference(options.quick);
    const double fallback = SolverOptions{}.linkEpsilon;
    std::vector<std::string> perPoint;
    {
        SolverOptions defaults;
        HierarchicalSolver solver(box.scene, box.mesh, defaults, nullptr);
        for (int k = 0; k < 200 && solver.step().residual > kResidual; ++k) {
        }
        const std::vector<double> errors = pointErrors(solver, box, reference);
        const auto& points = cornellProbePoints();
        for (std::size_t i = 0; i < points.size(); ++i)
            perPoint.push_back("  " + std::string(points[i].where) + ": reference " +
                               formatNumber(reference.radiosity[i].x, 4) + ", " + formatNumber(reference.radiosity[i].y, 4) +
                               ", " + formatNumber(reference.radiosity[i].z, 4) + " W/m^2; worst band off by " +
                               percent(errors[i]));
    }
    const std::vector<double> tolerances =
        options.quick ? std::vector<double>{fallback, fallback / 10}
                      : std::vector<double>{10 * fallback, fallback, fallback / 3, fallback / 10, fallback / 30, fallback / 100};
    const int repeats = options.quick ? 1 : 3;
    std::vector<Measured> sweep;
    for (const double tolerance : tolerances) sweep.push_back(solveAt(box, tolerance, repeats, reference));

    // Issue #14's targets: the default within 0.5% mean and 1.5% worst in 0.12 s; some finer setting
    // within 0.2% mean in 3.4 s.
    const Measured* finest = nullptr;
    for (const Measured& m : sweep)
        if (m.tolerance < fallback && m.error.mean <= 0.002 && m.wall <= 3.4 && (!finest || m.wall < finest->wall)) finest = &m;
    for (const Measured& m : sweep) {
        std::string target = "-", verdict = "-";
        if (m.tolerance == fallback) {
            target = "0.5% / 1.5% in 0.12 s";
            const bool accurate = m.error.mean <= 0.005 && m.error.worst <= 0.015;
            verdict = (accurate ? std::string("accuracy met") : "accuracy missed") + ", time " + timeVerdict(m.wall, 0.12);
        } else if (m.tolerance < fallback) {
            target = "0.2% mean in 3.4 s";
            verdict = m.error.mean <= 0.002 ? "accuracy met, time " + timeVerdict(m.wall, 3.4) : "accuracy missed";
        }
        table.rows.push_back({formatNumber(m.tolerance, 2) + (m.tolerance == fallback ? " (default)" : ""),
                              std::to_string(m.leaves), std::to_string(m.links), std::to_string(m.steps),
                              formatNumber(m.wall), percent(m.error.mean), percent(m.error.worst), m.error.worstWhere,
                              target, verdict});
    }

    // RenderPark at equal accuracy: Radiant's fastest tolerance at least as accurate as each setting.
    const std::vector<PublishedPeer> peers = {{"RenderPark, default threshold", 0.0048, 0.015, 0.25},
                                     {"RenderPark, 10x finer", 0.0029, -1, 1.4},
                                     {"RenderPark, 100x finer", 0.0018, -1, 6.8}};
    for (const PublishedPeer& peer : peers) {
        const Measured* match = nullptr;
        for (const Measured& m : sweep)
            if (m.error.mean <= peer.mean && (peer.worst < 0 || m.error.worst <= peer.worst) &&
                (!match || m.wall < match->wall))
                match = &m;
        std::string figure = percent(peer.mean) + (peer.worst > 0 ? " / " + percent(peer.worst) : "") + " in " +
                             formatNumber(peer.seconds) + " s";
        table.rows.push_back({peer.setting, "-", "-", "-", "-", "-", "-", "-", figure,
                              match ? "Radiant at " + formatNumber(match->tolerance, 2) + ": " + percent(match->error.mean) +
                                          " / " + percent(match->error.worst) + " in " + formatNumber(match->wall) +
                                          " s (" + formatNumber(peer.seconds / match->wall, 2) + "x faster)"
                                    : "no tolerance swept is as accurate"});
    }
    // Issue #20 item 6: a tessellated sphere in a closed room (hundreds of small roots) at the default.
    const SphereRoomAccuracy sphere = sphereRoomAccuracy(options.quick);
    table.rows.push_back({"sphere room, default", std::to_string(sphere.leaves), std::to_string(sphere.links), "-", "-",
                          percent(sphere.worstSurface) + " (" + sphere.worstSurfaceName + ")", percent(sphere.worstPoint),
                          "sphere points", "2% per surface vs Gauss-Seidel",
                          sphere.worstSurface <= 0.02 ? "met" : "missed"});
    table.notes = {
        "The Cornell box at 0.01 m^2 patches (10x the lab's default area: this reading does not use the patches),",
        "SolverOptions defaults but the link tolerance; wall time from",
        "set-up (element tree, root links) to residual 1e-3, median of " + std::to_string(repeats) +
            " runs on the shared 2-core machine; patch values gathered over the links included.",
        "Error at " + std::to_string(cornellProbePoints().size()) +
            " points (floor, ceiling, walls, both blocks' sides, corners and penumbrae), each band: the",
        "hierarchical value at the point (HierarchicalSolver::radiosityAt: the links' own gather there, without the",
        "patches; the Probe panel, `radiant probe` and the accuracy table read M + rho E gathered over the patches",
        "instead, which is what issue 14's targets are judged on) against the path tracer of radiometry/reference, traced to a",
        "relative standard error of " + percent(reference.targetStandardError) + " (worst reached " +
            percent(reference.worstStandardError) + ").",
        std::string("Finest setting meeting 0.2% in 3.4 s: ") +
            (finest ? formatNumber(finest->tolerance, 2) + " (" + percent(finest->error.mean) + " in " +
                          formatNumber(finest->wall) + " s)"
                    : "none swept") + ".",
        "RenderPark rows: the issue's measurements on this machine (against a path tracer); Radiant's fastest swept",
        "tolerance whose mean (and worst, where stated) is no larger.",
        "Sphere room row (tests/data/curved/sphere_room.gltf's scene, 0.02 m^2 patches): mean error = the worst surface",
        "mean against Gauss-Seidel on the same mesh; worst error = the sphere's point values against the path tracer",
        "(worst patch " + percent(sphere.worstPatch) + "); sphere mean " + formatNumber(sphere.sphereMean, 4) + " W/m^2, Gauss-Seidel " +
            formatNumber(sphere.sphereMeanGaussSeidel, 4) + ".",
        "At the default tolerance, per point (reference R, G, B):",
    };
    for (const std::string& line : sphere.points) table.notes.insert(table.notes.end() - 1, "  " + line);
    table.notes.insert(table.notes.end(), perPoint.begin(), perPoint.end());
    return table;
}

} // namespace radiant::app
