// `radiant probe SCENE --point X,Y,Z --normal X,Y,Z [--target SURFACE]`: solve the scene, then read
// radiosity, radiance, irradiance and a target surface's solid angle and form factor at one point
// (radiometry/probe/Probe.h), printed as the JSON of docs/ARCHITECTURE. --photometric adds lx and
// cd/m^2 by Radiance's convention (radiometry/units/Photometry.h). A point within 1 mm of a surface
// (a reading copied with too few digits) is moved onto it, with a warning on stderr and in the
// JSON's "warnings".
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/CommandLine.h"
#include "app/cli/JsonRgb.h"
#include "app/cli/ProbeCommandLine.h"
#include "app/cli/ViewArguments.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/units/Photometry.h"

namespace radiant::app {

namespace {

/// m: farther than this from every surface, a point is refused rather than moved.
constexpr double kSnapDistance = 1e-3;

struct ProbeCommandOptions {
    std::string scene;
    std::string point;
    std::string normal;
    std::string target;  ///< empty: the first emitting surface
    std::string method;  ///< empty: chosen by the scene's size (DefaultMethod.h)
    double maxPatchArea = kSolveDefaults.maxPatchArea;
    double tolerance = kSolveDefaults.tolerance;
    std::size_t maxIterations = kSolveDefaults.maxIterations;
    double linkTolerance = SolverOptions{}.linkEpsilon;
    ViewArguments view{"", "", 0, "--look-at"};  // --target names the measured surface
    std::string json = "-";
    bool photometric = false;
    GroupingFlags grouping;
};

/// The named surface, else the first emitting one; none for a scene lit only by punctual lights.
std::optional<std::size_t> chooseTarget(const Scene& scene, const std::string& name) {
    if (!name.empty()) {
        const std::size_t found = scene.findSurface(name);
        if (found == Scene::npos) {
            std::string known;
            for (const Surface& s : scene.surfaces) known += (known.empty() ? "'" : ", '") + s.name + "'";
            throw RadiantError({scene.name, "--target"}, "no surface '" + name + "' (surfaces: " + known + ")");
        }
        return found;
    }
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s)
        if (scene.materials.at(scene.surfaces[s].material).emits()) return s;
    if (!scene.lights.empty()) return std::nullopt;
    throw RadiantError({scene.name, "--target"}, "the scene has no emitting surface; name a target");
}

int runProbe(const ProbeCommandOptions& options) {
    const glm::dvec3 point = parseVector(options.point, "--point");
    const glm::dvec3 normal = parseVector(options.normal, "--normal");
    if (!(options.maxPatchArea > 0))
        throw RadiantError({"", "--max-patch-area"}, "must be > 0, got " + std::to_string(options.maxPatchArea));
    if (!(options.tolerance > 0))
        throw RadiantError({"", "--tolerance"}, "must be > 0, got " + std::to_string(options.tolerance));
    if (!(options.linkTolerance > 0))
        throw RadiantError({"", "--link-tolerance"}, "must be > 0, got " + std::to_string(options.linkTolerance));
    if (!options.method.empty()) (void)parseMethod(options.method);  // a bad name fails before the load

    const Scene scene = loadSceneArgument(options.scene);
    const std::optional<std::size_t> target = chooseTarget(scene, options.target);
    const CommandSystem system = meshForCommand(options.method, scene, options.maxPatchArea, options.grouping.mode());
    const MethodChoice& choice = system.choice;
    const SolverMethod method = choice.method;
    const PatchMesh& mesh = system.mesh;
    // One BVH for the scene: the mesher's, the probe's visibility and the solver's share it.
    const std::shared_ptr<const RayCaster>& rays = system.rays;
    const Probe probe(scene, mesh, rays.get());
    std::vector<std::string> warnings = scene.warnings;
    glm::dvec3 onSurface = point;
    if (const std::optional<SurfaceSnap> snap = probe.snapOntoSurface(point, kSnapDistance)) {
        char distance[32], chordError[32];
        std::snprintf(distance, sizeof distance, "%.3g", snap->distance);
        std::snprintf(chordError, sizeof chordError, "%.3g", snap->chordError);
        const std::string curved = snap->chordError > 0 ? std::string(", within the chord error of its tessellation (") +
                                                              chordError + " m: the smooth surface its facets stand for)"
                                                        : std::string();
        const std::string warning = "--point: (" + roundTripVector(point) + ") lies " + distance + " m off '" +
                                    scene.surfaces[snap->surface].name + "'" + curved + "; moved onto it, to (" +
                                    roundTripVector(snap->point) + ")";
        std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
        warnings.push_back(warning);
        onSurface = snap->point;
    }
    const SurfacePoint at = probe.locate(onSurface, normal);  // bad input fails before the long solve

    std::vector<Rgb> radiosity;
    std::string solution;
    std::size_t iterations = 0;
    double residual = 1;
    {
        SolverOptions solverOptions;
        solverOptions.rays = rays;
        solverOptions.linkEpsilon = options.linkTolerance;
        solverOptions.view = viewFromArguments(options.view, scene);
        const std::unique_ptr<Solver> solver = makeCommandSolver(scene, system, solverOptions);
        while (iterations < options.maxIterations) {
            residual = solver->step().residual;
            ++iterations;
            if (residual <= options.tolerance) break;
        }
        radiosity = solver->solution();
        solution = "solved";
    }

    const ProbeReading reading = probe.measure(at, normal, radiosity, target);
    nlohmann::json out;
    out["scene"] = scene.name;
    out["method"] = std::string(methodName(method));
    out["method_reason"] = choice.reason.empty() ? std::string("given by --method") : choice.reason;
    out["grouped"] = system.groups != nullptr;
    out["grouping_reason"] = system.groupingReason;
    out["solution"] = solution;
    out["iterations"] = iterations;
    if (solution == "solved") out["residual"] = residual;
    out["patches"] = mesh.size();
    out["unknowns"] = system.groups ? system.groups->size() : mesh.size();
    out["point"] = rgbArray<nlohmann::json>(reading.at.point);
    out["normal"] = rgbArray<nlohmann::json>(reading.normal);
    out["surface"] = scene.surfaces[reading.at.surface].name;
    out["radiosity_W_m2"] = rgbArray<nlohmann::json>(reading.radiosity.value());
    out["interpolated_radiosity_W_m2"] = rgbArray<nlohmann::json>(reading.interpolatedRadiosity.value());
    out["patch_radiosity_W_m2"] = rgbArray<nlohmann::json>(reading.patchRadiosity.value());
    out["radiance_W_m2_sr"] = rgbArray<nlohmann::json>(reading.radiance.value());
    out["irradiance_W_m2"] = rgbArray<nlohmann::json>(reading.irradiance.value());
    out["direct_irradiance_W_m2"] = rgbArray<nlohmann::json>(reading.directIrradiance.value());
    if (options.photometric) {
        out["illuminance_lx"] = illuminanceLux(reading.irradiance);
        out["direct_illuminance_lx"] = illuminanceLux(reading.directIrradiance);
        out["luminance_cd_m2"] = luminanceCdPerM2(reading.radiance);
        out["photometric_convention"] = "179 lm/W, Y = 0.265 R + 0.670 G + 0.065 B (Radiance)";
    }
    if (reading.target) {
        const TargetReading& t = *reading.target;
        out["target"] = {{"name", t.name},
                         {"solid_angle_sr", t.solidAngle.value()},
                         {"projected_solid_angle_sr", t.projectedSolidAngle.value()},
                         {"form_factor", t.formFactor},
                         {"unoccluded_solid_angle_sr", t.unoccludedSolidAngle.value()},
                         {"unoccluded_form_factor", t.unoccludedFormFactor}};
    }
    out["warnings"] = warnings;

    writeText(options.json, out.dump(2) + "\n", "--json");
    return 0;
}

} // namespace

Subcommand addProbeCommand(CLI::App& root) {
    auto options = std::make_shared<ProbeCommandOptions>();
    CLI::App* sub = root.add_subcommand("probe", "Read B, L, E and a target's solid angle and form factor at a point");
    sub->add_option("scene", options->scene, "glTF file or built-in scene name")->required();
    sub->add_option("--point", options->point, "X,Y,Z on a surface, metres")->required();
    sub->add_option("--normal", options->normal, "X,Y,Z: the probe's facing direction")->required();
    sub->add_option("--target", options->target, "surface to measure (default: the first emitting surface; none in a scene lit only by lights)");
    sub->add_option("--method", options->method, methodOptionHelp());
    sub->add_option("--max-patch-area", options->maxPatchArea, "m^2")->capture_default_str();
    sub->add_option("--tolerance", options->tolerance, "solve until this residual")->capture_default_str();
    sub->add_option("--max-iterations", options->maxIterations, "or this many steps")->capture_default_str();
    sub->add_option("--link-tolerance", options->linkTolerance, "hierarchical/importance: refine a link while the radiosity error it may leave exceeds this fraction of the emitted power (smaller: more accurate, slower)")->capture_default_str();
    addViewOptions(*sub, options->view);
    sub->add_option("--json", options->json, "FILE, or - for standard output")->capture_default_str();
    addGroupingFlags(*sub, options->grouping);
    sub->add_flag("--photometric", options->photometric,
                  "Also give illuminance_lx and luminance_cd_m2 (179 lm/W, Y = 0.265 R + 0.670 G + 0.065 B, Radiance's convention)");
    return {sub, [options] { return runProbe(*options); }};
}

} // namespace radiant::app
