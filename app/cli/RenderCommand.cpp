// `radiant render SCENE --png FILE`: load, mesh, solve to the default tolerance (no solver thread:
// the command line waits anyway), then draw from a glTF camera (--camera), a view (--eye/--target/--fov)
// or the scene's home camera into an offscreen framebuffer of a headless EGL context (a hidden
// window's where EGL is missing) and write the PNG.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "app/cli/CommandLine.h"
#include "app/cli/ViewArguments.h"
#include "app/window/OffscreenContext.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/Screenshot.h"
#include "render/camera/HomeCamera.h"
#include "render/display/LegendImage.h"

namespace radiant::app {
namespace {

struct RenderOptions {
    std::string scene;
    std::string png;
    int width = 1600;
    int height = 1000;
    std::string method;  ///< empty: chosen by the scene's size (DefaultMethod.h)
    double maxPatchArea = kSolveDefaults.maxPatchArea;
    double tolerance = kSolveDefaults.tolerance;
    std::size_t maxIterations = kSolveDefaults.maxIterations;
    double linkTolerance = SolverOptions{}.linkEpsilon;
    ViewArguments view;
    bool falseColour = false;
    bool logScale = false;
    bool photometric = false;
    bool flat = false;
    bool wireframe = false;
    GroupingFlags grouping;
    float exposureStops = 0.0f;
    std::string camera;  ///< a glTF camera's name or index; empty: the home camera
};

// The lab's background: a dark neutral grey that no wall colour competes with.
const glm::vec3 kRenderBackground{0.075f, 0.08f, 0.09f};

/// --camera: the scene's camera of that name, else of that index (names win: "1" may be a name).
render::Camera sceneCamera(const Scene& scene, const std::string& wanted) {
    const SceneCamera* found = nullptr;
    for (const SceneCamera& camera : scene.cameras)
        if (camera.name == wanted && !found) found = &camera;
    if (!found && !wanted.empty() && wanted.find_first_not_of("0123456789") == std::string::npos && wanted.size() < 10) {
        const std::size_t index = std::stoul(wanted);
        if (index < scene.cameras.size()) found = &scene.cameras[index];
    }
    if (!found) {
        std::string known;
        for (std::size_t c = 0; c < scene.cameras.size(); ++c)
            known += (c == 0 ? "" : ", ") + std::to_string(c) + " '" + scene.cameras[c].name + "'";
        throw RadiantError({scene.name, "--camera"}, "no camera '" + wanted + "' (" +
                                                         (known.empty() ? std::string("the scene has no cameras") : "cameras: " + known) + ")");
    }
    render::Camera camera;
    camera.eye = found->position;
    camera.forward = found->forward;
    camera.up = found->up;
    camera.fieldOfView = Radians(found->verticalFieldOfView);
    // Far enough for every corner of the scene; the near plane stays the lab's 1 cm.
    glm::dvec3 lo, hi;
    sceneBounds(scene, lo, hi);
    double farthest = 0;
    for (int corner = 0; corner < 8; ++corner)
        farthest = std::max(farthest, glm::length(glm::dvec3(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                                              corner & 4 ? hi.z : lo.z) - camera.eye));
    camera.farPlane = std::max(camera.farPlane, 1.1 * farthest);
    return camera;
}

int runRender(const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw RadiantError({"", "--width/--height"}, "image size must be 1..16384 pixels, got " +
                                                         std::to_string(options.width) + " x " +
                                                         std::to_string(options.height));
    if (!(options.maxPatchArea > 0))
        throw RadiantError({"", "--max-patch-area"}, "must be > 0, got " + std::to_string(options.maxPatchArea));
    if (!(options.linkTolerance > 0))
        throw RadiantError({"", "--link-tolerance"}, "must be > 0, got " + std::to_string(options.linkTolerance));
    if (!(options.tolerance > 0))
        throw RadiantError({"", "--tolerance"}, "must be > 0, got " + std::to_string(options.tolerance));
    if (!options.method.empty()) (void)parseMethod(options.method);  // a bad name fails before the load
    // The GL context first, so a missing one fails before the solve rather than after.
    const OffscreenContext context("radiant render");

    LoadedScene loaded = loadScene(options.scene);
    for (const std::string& warning : loaded.scene.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
    const Scene& scene = loaded.scene;
    const CommandSystem system = meshForCommand(options.method, scene, options.maxPatchArea, options.grouping.mode());
    const PatchMesh& mesh = system.mesh;
    const SolverMethod method = system.choice.method;
    // One view for the picture and for importance's refinement: what is drawn is what was refined.
    const double aspect = static_cast<double>(options.width) / static_cast<double>(options.height);
    const std::optional<View> view = viewFromArguments(options.view, scene, aspect);
    SolverOptions solverOptions;
    solverOptions.linkEpsilon = options.linkTolerance;
    solverOptions.view = view;
    const std::unique_ptr<Solver> solver = makeCommandSolver(scene, system, solverOptions);
    const render::Camera camera = !options.camera.empty() ? sceneCamera(scene, options.camera)
                                  : view                  ? render::cameraFromView(*view)
                                                          : render::homeCamera(scene);
    IterationStats stats;
    do stats = solver->step();
    while (stats.residual > options.tolerance && stats.iteration < options.maxIterations);

    render::PatchRenderer renderer;
    renderer.setMesh(scene, mesh, 1);
    renderer.setRadiosity(solver->solution(), 1, -1);
    render::DisplaySettings settings;
    settings.exposureStops = options.exposureStops;
    // A converged picture is keyed on itself, as --exposure documents (the lab's default keys on the emitters).
    settings.exposureKey = render::ExposureKey::Automatic;
    settings.colourMode = options.falseColour ? render::ColourMode::FalseColour : render::ColourMode::ToneMapped;
    settings.logScale = options.logScale;
    settings.photometric = options.photometric;
    settings.shading = options.flat ? render::Shading::Flat : render::Shading::Smooth;
    settings.wireframe = options.wireframe;
    settings.highlightShooter = false;
    renderer.setSettings(settings);
    renderer.prepare();
    render::ImageRgb8 image = render::renderOffscreen(renderer, camera, options.width, options.height, kRenderBackground);
    // A false-colour figure means nothing without its scale: the legend goes into the picture.
    if (options.falseColour) render::paintLegend(image, renderer.legend());
    render::writePng(image, options.png);
    std::printf("%s: %zu patches, %s, %zu iterations, residual %.3g; wrote %s (%d x %d)\n", options.scene.c_str(),
                mesh.size(), std::string(methodName(method)).c_str(), stats.iteration, stats.residual,
                options.png.c_str(), options.width, options.height);
    const render::ColourLegend legend = renderer.legend();
    if (options.falseColour)
        std::printf("false colour: %s %g to %g %s (%s) on viridis\n", legend.quantity, legend.minW_m2, legend.maxW_m2,
                    legend.unit, legend.logScale ? "log" : "linear");
    else
        std::printf("exposure %+g stops: key %.4g W/m^2 (mean luminance of lit non-emitters), ACES-fitted, sRGB\n",
                    static_cast<double>(options.exposureStops), renderer.exposureKeyW_m2());
    return 0;
}

} // namespace

Subcommand addRenderCommand(CLI::App& root) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* sub = root.add_subcommand("render", "Solve a scene and write a picture of it from its home camera or --eye/--target/--fov");
    sub->add_option("scene", options->scene, "glTF file or built-in scene name")->required();
    sub->add_option("--png", options->png, "PNG file to write")->required();
    sub->add_option("--width", options->width, "image width in pixels")->capture_default_str();
    sub->add_option("--height", options->height, "image height in pixels")->capture_default_str();
    sub->add_option("--method", options->method, methodOptionHelp());
    sub->add_option("--max-patch-area", options->maxPatchArea, "largest patch in m^2")->capture_default_str();
    sub->add_option("--link-tolerance", options->linkTolerance, "hierarchical/importance: refine a link while the radiosity error it may leave exceeds this fraction of the emitted power (smaller: more accurate, slower)")->capture_default_str();
    sub->add_option("--tolerance", options->tolerance, "solve until this residual")->capture_default_str();
    sub->add_option("--max-iterations", options->maxIterations, "or this many steps")->capture_default_str();
    addViewOptions(*sub, options->view);
    sub->add_flag("--false-colour,--false-color", options->falseColour,
                  "total radiosity in W/m^2 through viridis instead of the tone-mapped picture, with its legend");
    sub->add_flag("--log-scale", options->logScale, "false colour on a log scale (3 decades)");
    sub->add_flag("--photometric", options->photometric,
                  "false colour maps the illuminance each patch receives in lx (179 lm/W, Y = 0.265 R + 0.670 G + 0.065 B)");
    addGroupingFlags(*sub, options->grouping, "; each patch drawn with its group's radiosity");
    sub->add_flag("--flat", options->flat, "each patch its own radiosity (no interpolation)");
    sub->add_flag("--wireframe", options->wireframe, "draw the patch edges");
    sub->add_option("--exposure", options->exposureStops, "exposure in stops relative to the automatic key")
        ->capture_default_str();
    sub->add_option("--camera", options->camera, "the scene's camera (a glTF camera) by NAME or INDEX; default: the home view");
    return {sub, [options] { return runRender(*options); }};
}

} // namespace radiant::app
