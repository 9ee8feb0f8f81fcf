// `radiant render SCENE --png FILE`: load, mesh, solve to the default tolerance (no solver thread:
// the command line waits anyway), then draw from the scene's home camera (or --eye/--target/--fov)
// into an offscreen framebuffer of a hidden window's GL context and write the PNG.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/CommandLine.h"
#include "app/cli/ViewArguments.h"
#include "app/window/Window.h"
#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/Screenshot.h"
#include "render/camera/HomeCamera.h"

namespace radiant::app {
namespace {

struct RenderOptions {
    std::string scene;
    std::string png;
    int width = 1600;
    int height = 1000;
    std::string method{methodName(kSolveDefaults.method)};
    double maxPatchArea = kSolveDefaults.maxPatchArea;
    double tolerance = kSolveDefaults.tolerance;
    std::size_t maxIterations = kSolveDefaults.maxIterations;
    ViewArguments view;
    bool falseColour = false;
    bool logScale = false;
    bool flat = false;
    bool wireframe = false;
    float exposureStops = 0.0f;
};

// The lab's background: a dark neutral grey that no wall colour competes with.
const glm::vec3 kBackground{0.075f, 0.08f, 0.09f};

int runRender(const RenderOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw RadiantError({"", "--width/--height"}, "image size must be 1..16384 pixels, got " +
                                                         std::to_string(options.width) + " x " +
                                                         std::to_string(options.height));
    if (!(options.maxPatchArea > 0))
        throw RadiantError({"", "--max-patch-area"}, "must be > 0, got " + std::to_string(options.maxPatchArea));
    if (!(options.tolerance > 0))
        throw RadiantError({"", "--tolerance"}, "must be > 0, got " + std::to_string(options.tolerance));
    const SolverMethod method = parseMethod(options.method);
    // The GL context first, so a missing display fails before the solve rather than after. Any
    // window will do: the picture goes to a framebuffer of the requested size.
    const Window window({64, 64, "radiant render", /*visible=*/false, /*vsync=*/false});

    LoadedScene loaded = loadScene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
    const Scene& scene = loaded.scene;
    MeshingOptions meshing;
    meshing.maxPatchArea = options.maxPatchArea;
    const PatchMesh mesh = meshScene(scene, meshing);
    // One view for the picture and for importance's refinement: what is drawn is what was refined.
    const double aspect = static_cast<double>(options.width) / static_cast<double>(options.height);
    const std::optional<View> view = viewFromArguments(options.view, scene, aspect);
    SolverOptions solverOptions;
    solverOptions.view = view;
    const std::unique_ptr<Solver> solver = makeSolver(method, scene, mesh, solverOptions);
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
    settings.shading = options.flat ? render::Shading::Flat : render::Shading::Smooth;
    settings.wireframe = options.wireframe;
    settings.highlightShooter = false;
    renderer.setSettings(settings);
    const render::ImageRgb8 image =
        render::renderOffscreen(renderer, view ? render::cameraFromView(*view) : render::homeCamera(scene), options.width,
                                options.height, kBackground);
    render::writePng(image, options.png);
    std::printf("%s: %zu patches, %s, %zu iterations, residual %.3g; wrote %s (%d x %d)\n", options.scene.c_str(),
                mesh.size(), std::string(methodName(method)).c_str(), stats.iteration, stats.residual,
                options.png.c_str(), options.width, options.height);
    const render::ColourLegend legend = renderer.legend();
    if (options.falseColour)
        std::printf("false colour: total radiosity %g to %g W/m^2 (%s) on viridis\n", legend.minW_m2, legend.maxW_m2,
                    legend.logScale ? "log" : "linear");
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
    sub->add_option("--method", options->method,
                    "jacobi, gauss-seidel, progressive, hierarchical or importance")
        ->capture_default_str();
    sub->add_option("--max-patch-area", options->maxPatchArea, "largest patch in m^2")->capture_default_str();
    sub->add_option("--tolerance", options->tolerance, "solve until this residual")->capture_default_str();
    sub->add_option("--max-iterations", options->maxIterations, "or this many steps")->capture_default_str();
    addViewOptions(*sub, options->view);
    sub->add_flag("--false-colour,--false-color", options->falseColour,
                  "total radiosity in W/m^2 through viridis instead of the tone-mapped picture");
    sub->add_flag("--log-scale", options->logScale, "false colour on a log scale (3 decades)");
    sub->add_flag("--flat", options->flat, "each patch its own radiosity (no interpolation)");
    sub->add_flag("--wireframe", options->wireframe, "draw the patch edges");
    sub->add_option("--exposure", options->exposureStops, "exposure in stops relative to the automatic key")
        ->capture_default_str();
    return {sub, [options] { return runRender(*options); }};
}

} // namespace radiant::app
