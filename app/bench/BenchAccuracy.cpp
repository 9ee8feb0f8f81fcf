// How right each method is at its defaults (issue 14's targets): the built-in Cornell box meshed and
// solved as `radiant solve` and the lab do, read at points the way the probe reads them (E gathered
// at the point from the solution, B = M + rho E), against the path-traced rendering
// equation (radiometry/reference/) at the same points, traced until its standard error is under 0.2%.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/bench/AccuracyCheck.h"
#include "app/bench/BenchTable.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app {


BenchTable benchAccuracy(const BenchOptions& options) {
    BenchTable table{"Accuracy against the path-traced reference (Cornell box, each method at its defaults)",
                     {"method", "patches", "solve (s)", "B mean", "B worst (at)", "E mean", "E worst", "B vs mesh's own",
                      "patches vs mesh's own", "target", "verdict"},
                     {},
                     {}};
    const Scene scene = makeCornellBox();
    const RayCaster rays(scene);

    // The reference first: every method is compared with the same estimates.
    const double wantedError = options.quick ? 0.01 : 0.002;
    std::vector<AccuracyPoint> points = accuracyPoints(scene);
    const ReferenceTrace trace = traceReferences(scene, rays, points, wantedError,
                                                 std::chrono::duration<double>(options.quick ? 20.0 : 300.0));

    MeshingOptions meshing;
    meshing.maxPatchArea = kSolveDefaults.maxPatchArea;  // what the lab opens with and `solve` uses
    const PatchMesh mesh = meshScene(scene, meshing);
    const Probe probe(scene, mesh, &rays);
    const double tolerance = kSolveDefaults.tolerance;
    // Gauss-Seidel stepped on to this is the mesh's own answer: the method's distance from it at a
    // point is the solver's share of the error, its distance from the reference the mesh's.
    constexpr double kConverged = 1e-8;
    const double budget = options.quick ? 30.0 : 120.0;
    std::vector<ProbeReading> converged;
    std::vector<Rgb> convergedPatches;
    std::vector<std::vector<ProbeReading>> readings;
    std::vector<std::vector<Rgb>> solutions;
    const auto readAll = [&](const Probe& on, const std::vector<Rgb>& solution) {
        std::vector<ProbeReading> out;
        for (const AccuracyPoint& point : points) out.push_back(on.measure(point.at.point, point.at.normal, solution));
        return out;
    };
    // Set-up (form factors, links) and steps to the lab's tolerance, within the budget.
    struct TimedSolve {
        std::unique_ptr<Solver> solver;
        double seconds = 0, residual = 0;
        std::chrono::steady_clock::time_point start;
    };
    const auto solveOnce = [&](SolverMethod method, const PatchMesh& on) {
        TimedSolve run;
        run.start = std::chrono::steady_clock::now();
        run.solver = makeSolver(method, scene, on);
        run.residual = run.solver->lastStats().residual;
        while (run.residual > tolerance && secondsSince(run.start) < budget) run.residual = run.solver->step().residual;
        run.seconds = secondsSince(run.start);
        return run;
    };
    // A solve under a second is timed up to kTimedSolves times (as many as fit in kRepeatSeconds
    // after the first) and the median kept: one run of hierarchical's 0.15 s read 0.15-0.18 s on the
    // shared machine within minutes (session 21), across the 0.12 s target's verdict. The solutions
    // are the same (every method is seeded); the first run's solver is the one read.
    constexpr int kTimedSolves = 5;
    constexpr double kRepeatSeconds = 2.0;
    int mostRepeats = 1;
    const auto solveToTolerance = [&](SolverMethod method, const PatchMesh& on) {
        TimedSolve run = solveOnce(method, on);
        std::vector<double> seconds{run.seconds};
        const auto repeatStart = std::chrono::steady_clock::now();
        while (!options.quick && run.seconds < 1.0 && static_cast<int>(seconds.size()) < kTimedSolves &&
               secondsSince(repeatStart) + run.seconds < kRepeatSeconds)
            seconds.push_back(solveOnce(method, on).seconds);
        mostRepeats = std::max(mostRepeats, static_cast<int>(seconds.size()));
        run.seconds = median(seconds);
        return run;
    };
    const auto addRow = [&](const std::string& name, std::size_t patches, const TimedSolve& run, const MethodErrors& errors,
                            const std::string& target, std::string verdict) {
        if (run.residual > tolerance) verdict += " (residual " + formatNumber(run.residual, 2) + " after the budget)";
        table.rows.push_back({name, std::to_string(patches), formatNumber(run.seconds), percent(errors.meanB),
                              percent(errors.worstB) + " (" + errors.worstBAt + ")", percent(errors.meanE),
                              percent(errors.worstE), "-", "-", target, verdict});
    };
    for (const SolverMethodInfo& info : solverMethods()) {
        const SolverMethod method = info.method;
        const bool hierarchical = method == SolverMethod::Hierarchical;
        TimedSolve run = solveToTolerance(method, mesh);
        readings.push_back(readAll(probe, run.solver->solution()));
        solutions.push_back(run.solver->solution());
        const MethodErrors errors = errorsAgainstReference(points, readings.back());
        const AccuracyTarget target = accuracyTarget(method);
        std::string verdict = target.met(errors) ? "met" : "missed";
        if (hierarchical) verdict += "; time " + timeVerdict(run.seconds, 0.12);
        addRow(std::string(info.name), mesh.size(), run, errors, target.text + (hierarchical ? ", < 0.12 s" : ""), verdict);
        if (method == SolverMethod::GaussSeidel) {
            while (run.residual > kConverged && secondsSince(run.start) < 2 * budget)
                run.residual = run.solver->step().residual;
            converged = readAll(probe, run.solver->solution());
            convergedPatches = run.solver->solution();
        }
    }
    // The solver's share: each method's point value against converged Gauss-Seidel's on this mesh.
    for (std::size_t m = 0; m < readings.size() && !converged.empty(); ++m) {
        double mean = 0;
        for (std::size_t k = 0; k < points.size(); ++k)
            mean += std::abs(signedError(readings[m][k].radiosity.value(), converged[k].radiosity.value()));
        table.rows[m][7] = percent(mean / static_cast<double>(points.size()));
    }
    // The same per patch, over the whole mesh: what the 3D view shows and every reading gathers from.
    for (std::size_t m = 0; m < solutions.size() && !convergedPatches.empty(); ++m) {
        const PatchDistance d = patchDistance(mesh, solutions[m], convergedPatches);
        table.rows[m][8] = percent(d.mean) + ", " + std::to_string(d.over5Percent) + " over 5%";
    }
    // Issue 14's finer setting: hierarchical within 0.2% in under 3.4 s. The default mesh alone is
    // 0.24% off (converged Gauss-Seidel above), and half its patch area still 0.22% (hierarchical, which
    // converges to the mesh's answer since its rays were unbiased in penumbrae), so the finer setting
    // takes a third of the patches' area.
    {
        MeshingOptions finer;
        finer.maxPatchArea = meshing.maxPatchArea / 3;
        const PatchMesh finerMesh = meshScene(scene, finer);
        const TimedSolve run = solveToTolerance(SolverMethod::Hierarchical, finerMesh);
        const MethodErrors errors =
            errorsAgainstReference(points, readAll(Probe(scene, finerMesh, &rays), run.solver->solution()));
        const bool accurate = errors.meanB <= 0.002 && errors.meanE <= 0.002;
        addRow("hierarchical, finer: " + formatNumber(finer.maxPatchArea, 2) + " m^2 patches", finerMesh.size(), run,
               errors, "0.2% mean, < 3.4 s", std::string(accurate ? "met" : "missed") + "; time " + timeVerdict(run.seconds, 3.4));
    }

    table.notes = {
        "Errors are |method - reference| / reference per point and band, averaged (mean) or the largest (worst), over " +
            std::to_string(points.size()) + " points x 3 bands: floor, ceiling, back, green and red walls (two each) and",
        "the four sides of both blocks, each at least 5 cm from its face's edges. The method's E is gathered at the point from",
        "its solution and B = M + rho E, as the Probe panel and `radiant probe` read them. Meshing: the default",
        "(" + formatNumber(meshing.maxPatchArea, 2) + " m^2, " + std::to_string(mesh.size()) +
            " patches); solvers at their default options, stepped to residual " + formatNumber(tolerance, 2) +
            " (the lab's tolerance); solve = set-up (form factors, links) + steps, wall clock" +
            (mostRepeats > 1 ? ": the median of up to " + std::to_string(mostRepeats) +
                                   " runs where one takes under 1 s (as many as fit in " + formatNumber(kRepeatSeconds) + " s)."
                             : std::string(", one run.")),
        "B vs mesh's own: the method's B at the points against Gauss-Seidel's on the same mesh stepped to residual " +
            formatNumber(kConverged, 2) + " (the solver's share of the error; the rest is the mesh's and the point's).",
        "Patches vs mesh's own: the same per patch, each patch's largest band error averaged over the lit patches by area,",
        "and how many patches are over 5% (Gauss-Seidel's own rays, 16 a pair, are in it too).",
        "Reference: radiometry/reference/ path tracer, " + std::to_string(trace.paths) + " paths in " +
            formatNumber(trace.seconds) + " s; every point traced until its standard error is under " +
            percent(wantedError) + " of E in every band (largest reached: " + percent(trace.worstError) + ").",
        "Targets (issue 14): every method within 1% mean and 3% worst; hierarchical within 0.5% / 1.5% in under 0.12 s,",
        "and within 0.2% at a finer setting in under 3.4 s (the last row: the default link tolerance on patches of a third of the",
        "default area, timed as the rows above).",
    };
    table.notes.emplace_back("Per point: reference B, then converged Gauss-Seidel on this mesh against it (the mesh's share):");
    table.notes.emplace_back("  at the point (M + rho E gathered), the patch's own B, B interpolated from the patches; then each");
    table.notes.emplace_back("  method's B against converged Gauss-Seidel at the point (the solver's share), in table order.");
    for (std::size_t k = 0; k < points.size(); ++k) {
        const AccuracyPoint& point = points[k];
        const Rgb b = point.reference.radiosity.value();
        char line[256];
        std::snprintf(line, sizeof line, "  %-30s (%.3f, %.3f, %.3f): B = (%.4g, %.4g, %.4g) W/m^2 +- %.2f%%",
                      point.label.c_str(), point.at.point.x, point.at.point.y, point.at.point.z, b.x, b.y, b.z,
                      100 * point.reference.relativeStandardError());
        std::string detail = line;
        if (!converged.empty()) {
            const ProbeReading& c = converged[k];
            detail += "; mesh " + signedPercent(signedError(c.radiosity.value(), b)) + " / patch " +
                      signedPercent(signedError(c.patchRadiosity.value(), b)) + " / interpolated " +
                      signedPercent(signedError(c.interpolatedRadiosity.value(), b)) + "; solvers";
            for (const auto& method : readings)
                detail += " " + signedPercent(signedError(method[k].radiosity.value(), c.radiosity.value()));
        }
        table.notes.push_back(detail);
    }
    return table;
}

} // namespace radiant::app
