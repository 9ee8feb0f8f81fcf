// `radiant reference SCENE --point X,Y,Z --normal X,Y,Z [--samples N | --seconds S] [--seed K]`:
// the rendering equation at one point by path tracing (radiometry/reference/), independent of the
// radiosity solvers, printed as JSON with its standard error per band.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/CommandLine.h"
#include "app/cli/JsonRgb.h"
#include "app/cli/ViewArguments.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/reference/PathTracer.h"
#include "radiometry/reference/ReferencePoint.h"
#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/SceneLibrary.h"

namespace radiant::app {

namespace {

struct ReferenceCommandOptions {
    std::string scene;
    std::string point;
    std::string normal;
    std::uint64_t samples = 1'000'000;
    double seconds = 0;
    bool timed = false;  ///< --seconds given: run that long instead of a sample count
    std::uint64_t seed = 1;
    std::string json = "-";
};

std::string formatValue(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

int runReference(const ReferenceCommandOptions& options) {
    const bool timed = options.timed;
    const glm::dvec3 point = parseVector(options.point, "--point");
    const glm::dvec3 normal = parseVector(options.normal, "--normal");
    if (timed && !(options.seconds > 0 && std::isfinite(options.seconds)))
        throw RadiantError({"", "--seconds"}, "must be a positive number of seconds, got " + formatValue(options.seconds));
    if (!timed && options.samples < 2)
        throw RadiantError({"", "--samples"}, "must be at least 2 (a standard error needs two), got " +
                                                  std::to_string(options.samples));

    const Scene scene = loadScene(options.scene).scene;
    const ReferencePoint at = locateReferencePoint(scene, point, normal);  // bad input fails before tracing
    const RayCaster rays(scene);
    const PathTracer tracer(scene, rays);
    ReferenceRunOptions runOptions;
    runOptions.seed = options.seed;
    ReferenceRun run(tracer, at, runOptions);
    ReferenceStop stop;
    if (timed)
        stop.time = std::chrono::duration<double>(options.seconds);
    else
        stop.samples = options.samples;
    const auto start = std::chrono::steady_clock::now();
    const ReferenceEstimate estimate = run.runUntil(stop);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    nlohmann::ordered_json out;
    out["scene"] = scene.name;
    out["surface"] = scene.surfaces[at.surface].name;
    out["point"] = rgbArray(at.point);
    out["normal"] = rgbArray(at.normal);
    out["radiosity_W_m2"] = rgbArray(estimate.radiosity.value());
    out["irradiance_W_m2"] = rgbArray(estimate.irradiance.value());
    out["standard_error_W_m2"] = {{"radiosity_W_m2", rgbArray(estimate.radiosityStandardError)},
                                  {"irradiance_W_m2", rgbArray(estimate.irradianceStandardError)}};
    out["samples"] = estimate.samples;
    out["reflectance"] = rgbArray(estimate.reflectance);
    out["exitance_W_m2"] = rgbArray(estimate.exitance.value());
    out["seed"] = options.seed;
    out["seconds"] = seconds;

    writeText(options.json, out.dump(2) + "\n", "--json");
    return 0;
}

} // namespace

Subcommand addReferenceCommand(CLI::App& root) {
    auto options = std::make_shared<ReferenceCommandOptions>();
    CLI::App* sub = root.add_subcommand(
        "reference", "Path-trace B and E at a point: the rendering equation, independent of every radiosity method");
    sub->add_option("scene", options->scene, "glTF file or built-in scene name")->required();
    sub->add_option("--point", options->point, "X,Y,Z on a surface, metres")->required();
    sub->add_option("--normal", options->normal, "X,Y,Z: the surface's front (within 5 degrees of its normal)")
        ->required();
    CLI::Option* samples =
        sub->add_option("--samples", options->samples, "paths to trace (deterministic for a seed)")->capture_default_str();
    CLI::Option* seconds = sub->add_option("--seconds", options->seconds, "trace for this long instead")
                               ->each([options](const std::string&) { options->timed = true; });
    samples->excludes(seconds);
    sub->add_option("--seed", options->seed, "random seed")->capture_default_str();
    sub->add_option("--json", options->json, "FILE, or - for standard output")->capture_default_str();
    return {sub, [options] { return runReference(*options); }};
}

} // namespace radiant::app
