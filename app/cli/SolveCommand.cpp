// `radiant solve SCENE`: mesh, build the solver, step to the tolerance, write JSON and CSV
// (formats in docs/ARCHITECTURE: one summary per surface, one row per patch).
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli/CommandLine.h"
#include "app/cli/JsonRgb.h"
#include "app/cli/ViewArguments.h"
#include "app/solver/ConvergenceCsv.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/sources/DiffuseEmitter.h"
#include "radiometry/units/Photometry.h"

namespace radiant::app {

namespace {

struct SolveOptions {
    std::string scene;
    std::string method;  ///< empty: chosen by the scene's size (DefaultMethod.h)
    double maxPatchArea = kSolveDefaults.maxPatchArea;
    double tolerance = kSolveDefaults.tolerance;
    std::size_t maxIterations = kSolveDefaults.maxIterations;
    double linkTolerance = SolverOptions{}.linkEpsilon;
    ViewArguments view;
    std::string json;
    std::string csv;
    bool photometric = false;
    GroupingFlags grouping;
};

double elapsedSeconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A one-line bar on stderr while `progress` runs, when stderr is a terminal; silent otherwise.
class ProgressLine {
public:
    ProgressLine(const Progress& progress, std::string label) {
        if (!isatty(STDERR_FILENO)) return;
        printer_ = std::jthread([&progress, label = std::move(label)](std::stop_token stop) {
            while (!stop.stop_requested()) {
                const double fraction = progress.fraction();
                const int filled = static_cast<int>(fraction * 30);
                std::fprintf(stderr, "\r%s [%s%s] %5.1f%%", label.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                             std::string(static_cast<std::size_t>(30 - filled), ' ').c_str(), 100 * fraction);
                std::fflush(stderr);
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
            std::fprintf(stderr, "\r%s\r", std::string(label.size() + 42, ' ').c_str());
        });
    }

private:
    std::jthread printer_;
};

void checkPositive(double value, const char* option) {
    if (!(value > 0)) throw RadiantError({"", option}, "must be > 0, got " + std::to_string(value));
}

int runSolve(const SolveOptions& options) {
    checkPositive(options.maxPatchArea, "--max-patch-area");
    checkPositive(options.tolerance, "--tolerance");
    checkPositive(options.linkTolerance, "--link-tolerance");
    if (!options.method.empty()) (void)parseMethod(options.method);  // a bad name fails before the load

    const auto meshStart = std::chrono::steady_clock::now();
    const Scene scene = loadSceneArgument(options.scene);
    const CommandSystem system = meshForCommand(options.method, scene, options.maxPatchArea, options.grouping.mode());
    const MethodChoice& choice = system.choice;
    const SolverMethod method = choice.method;
    const PatchMesh& mesh = system.mesh;
    const std::shared_ptr<const PatchGroups>& groups = system.groups;
    const double meshSeconds = elapsedSeconds(meshStart);

    const auto formFactorStart = std::chrono::steady_clock::now();
    Progress progress;
    std::unique_ptr<Solver> solver;
    {
        const ProgressLine bar(progress, "form factors");
        SolverOptions solverOptions;
        solverOptions.linkEpsilon = options.linkTolerance;
        solverOptions.view = viewFromArguments(options.view, scene);
        solver = makeCommandSolver(scene, system, solverOptions, &progress);
    }
    const double formFactorSeconds = elapsedSeconds(formFactorStart);

    const auto solveStart = std::chrono::steady_clock::now();
    while (solver->lastStats().residual > options.tolerance && solver->lastStats().iteration < options.maxIterations)
        solver->step();
    const double solveSeconds = elapsedSeconds(solveStart);
    const IterationStats& stats = solver->lastStats();
    if (stats.residual > options.tolerance)
        std::fprintf(stderr, "radiant: warning: residual %.3g above the tolerance %.3g after %zu iterations\n",
                     stats.residual, options.tolerance, stats.iteration);

    const std::vector<Rgb>& B = solver->solution();
    nlohmann::ordered_json surfaces = nlohmann::ordered_json::array();
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Material& material = scene.materials[scene.surfaces[s].material];
        double area = 0;
        Rgb power(0.0);
        for (std::size_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
            area += mesh.patches[i].area;
            power += mesh.patches[i].area * B[i];
        }
        const Rgb radiosity = area > 0 ? power / area : Rgb(0.0);
        const std::size_t patches = mesh.surfaceFirstPatch[s + 1] - mesh.surfaceFirstPatch[s];
        nlohmann::ordered_json surface = {{"name", scene.surfaces[s].name},
                                          {"area_m2", area},
                                          {"patches", patches},
                                          {"unknowns", groups ? groups->surfaceFirstGroup[s + 1] - groups->surfaceFirstGroup[s] : patches},
                                          {"reflectance", rgbArray(material.reflectance)},
                                          {"exitance_W_m2", rgbArray(material.exitance.value())},
                                          {"radiosity_W_m2", rgbArray(radiosity)},
                                          {"power_W", rgbArray(power)}};
        if (options.photometric) {
            surface["luminous_exitance_lm_m2"] = illuminanceLux(RadiosityRgb(radiosity));
            surface["luminance_cd_m2"] = luminanceCdPerM2(radianceFromRadiosity(RadiosityRgb(radiosity)));
            surface["luminous_flux_lm"] = luminousFluxLumen(PowerRgb(power));
        }
        surfaces.push_back(std::move(surface));
    }
    const nlohmann::ordered_json report = {
        {"scene", scene.name},
        {"method", std::string(methodName(method))},
        {"method_reason", choice.reason.empty() ? nlohmann::ordered_json("given by --method") : nlohmann::ordered_json(choice.reason)},
        {"patches", mesh.size()},
        {"unknowns", groups ? groups->size() : mesh.size()},
        {"grouped", groups != nullptr},
        {"grouping_reason", system.groupingReason},
        {"iterations", stats.iteration},
        {"residual", stats.residual},
        {"seconds", {{"mesh", meshSeconds}, {"form_factors", formFactorSeconds}, {"solve", solveSeconds}}},
        {"lights", scene.lights.size()},
        {"surfaces", surfaces},
        {"warnings", scene.warnings}};

    if (!options.json.empty()) writeText(options.json, report.dump(2) + "\n", "--json");
    if (!options.csv.empty()) {
        std::string csv = "patch,surface,area_m2,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b\n";
        char line[512];
        for (std::size_t i = 0; i < mesh.size(); ++i) {
            const Patch& p = mesh.patches[i];
            std::snprintf(line, sizeof line, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", p.area, p.centroid.x,
                          p.centroid.y, p.centroid.z, p.normal.x, p.normal.y, p.normal.z, B[i].x, B[i].y, B[i].z);
            csv += std::to_string(i) + "," + csvField(scene.surfaces[p.surface].name) + line;
        }
        writeText(options.csv, csv, "--csv");
    }
    if (options.json != "-" && options.csv != "-") {
        const std::string grouped = groups ? " in " + std::to_string(groups->size()) + " groups" : "";
        std::printf("%s: %s, %zu patches%s, %zu iterations, residual %.3g; seconds: mesh %.3f, form factors %.3f, solve %.3f\n",
                    scene.name.c_str(), std::string(methodName(method)).c_str(), mesh.size(), grouped.c_str(), stats.iteration,
                    stats.residual, meshSeconds, formFactorSeconds, solveSeconds);
        for (const auto& surface : surfaces) {
            const auto& b = surface["radiosity_W_m2"];
            if (options.photometric)
                std::printf("  %-16s L = %.4g cd/m^2, M = %.4g lm/m^2\n", surface["name"].get<std::string>().c_str(),
                            surface["luminance_cd_m2"].get<double>(), surface["luminous_exitance_lm_m2"].get<double>());
            else
                std::printf("  %-16s B = (%.4g, %.4g, %.4g) W/m^2\n", surface["name"].get<std::string>().c_str(),
                            b[0].get<double>(), b[1].get<double>(), b[2].get<double>());
        }
    }
    return 0;
}

} // namespace

Subcommand addSolveCommand(CLI::App& root) {
    auto options = std::make_shared<SolveOptions>();
    CLI::App* sub = root.add_subcommand("solve", "Solve a scene's radiosity without a window; write JSON and CSV");
    sub->add_option("scene", options->scene, "glTF file or built-in scene name")->required();
    sub->add_option("--method", options->method, methodOptionHelp());
    sub->add_option("--max-patch-area", options->maxPatchArea, "Largest patch, m^2")->capture_default_str();
    sub->add_option("--tolerance", options->tolerance, "Stop at this residual (fraction of emitted power)")
        ->capture_default_str();
    sub->add_option("--max-iterations", options->maxIterations, "Stop after this many steps")->capture_default_str();
    sub->add_option("--link-tolerance", options->linkTolerance, "hierarchical/importance: refine a link while the radiosity error it may leave exceeds this fraction of the emitted power (smaller: more accurate, slower)")->capture_default_str();
    addViewOptions(*sub, options->view);
    sub->add_option("--json", options->json, "Write the per-surface summary as JSON to FILE, or '-' for stdout");
    sub->add_option("--csv", options->csv, "Write one row per patch as CSV to FILE, or '-' for stdout");
    addGroupingFlags(*sub, options->grouping);
    sub->add_flag("--photometric", options->photometric,
                  "Also give each surface's luminance (cd/m^2), luminous exitance (lm/m^2) and flux (lm): 179 lm/W, "
                  "Y = 0.265 R + 0.670 G + 0.065 B (Radiance's convention)");
    return {sub, [options] { return runSolve(*options); }};
}

} // namespace radiant::app
