// Screenshots for docs/screenshots that need a human's eye rather than a check: the hemisphere views,
// integrals and lecture demos panel by panel, the Hemisphere panel in the lab, the dome over a
// point in the 3D view, and each lecture demo in the lab's 3D view at a projector's UI scale. A developer's tool, run under a display:
//   xvfb-run -a -s "-screen 0 1600x1000x24 -noreset" build/radiant_screenshots docs/screenshots [demos]
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/Lab.h"
#include "app/panels/HemicubeSession.h"
#include "app/panels/HemispherePanel.h"
#include "app/panels/IntegralsPanel.h"
#include "app/panels/demos/LectureDemos.h"
#include "app/lessons/Lesson.h"
#include "app/ui/ImGuiLayer.h"
#include "app/window/Window.h"
#include "radiometry/hemicube/HemisphereProjection.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/Solver.h"
#include "render/GlContext.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/SceneTriangles.h"
#include "render/Screenshot.h"
#include "render/camera/Camera.h"
#include "render/hemicube/HemicubeRenderer.h"
#include "render/hemicube/HemisphereImage.h"
#include "render/hemisphere/HemisphereOverlay.h"

using namespace radiant;

namespace {

/// Draws `panel` alone in a window `width` wide for a few frames, then saves the window's part.
void shoot(app::Window& window, app::ImGuiLayer& ui, const std::function<void()>& drawPanel, const char* title,
           const std::filesystem::path& file, int width = 520) {
    render::ImageRgb8 image;
    int fbWidth = 0, fbHeight = 0;
    ImVec2 size{};
    for (int frame = 0; frame < 4; ++frame) {
        glfwPollEvents();
        ui.newFrame();
        window.framebufferSize(fbWidth, fbHeight);
        ImGui::SetNextWindowPos({0, 0});
        ImGui::SetNextWindowSize({static_cast<float>(width), 0});
        ImGui::Begin(title, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoCollapse);
        drawPanel();
        size = ImGui::GetWindowSize();
        ImGui::End();
        render::beginWindowFrame(fbWidth, fbHeight, {0, 0, fbWidth, fbHeight}, {0.075f, 0.08f, 0.09f});
        render::useWholeWindow(fbWidth, fbHeight);
        ui.render();
        if (frame == 3) image = render::readWindowPixels(fbWidth, fbHeight);
        window.swapBuffers();
    }
    // Crop to the panel's window.
    const int w = std::min(fbWidth, static_cast<int>(size.x)), h = std::min(fbHeight, static_cast<int>(size.y));
    render::ImageRgb8 cropped{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3)};
    for (int y = 0; y < h; ++y)
        std::copy_n(image.pixels.begin() + static_cast<std::ptrdiff_t>(y) * image.width * 3, w * 3,
                    cropped.pixels.begin() + static_cast<std::ptrdiff_t>(y) * w * 3);
    render::writePng(cropped, file);
    std::printf("wrote %s\n", file.string().c_str());
}

/// The scene, then the dome over it (the lab's order: only the scene hides the dome).
struct PatchesUnderDome final : render::SceneRenderer {
    PatchesUnderDome(const render::PatchRenderer& p, const render::HemisphereOverlay& d) : patches(p), dome(d) {}
    void draw(const render::Camera& camera, double aspect) const override {
        patches.draw(camera, aspect);
        dome.draw(camera, aspect);
    }
    const render::PatchRenderer& patches;
    const render::HemisphereOverlay& dome;
};

/// The hemisphere views, the integrals and the lecture demos, each panel alone.
void panels(const std::filesystem::path& dir) {
    app::Window window({1200, 1000, "hemisphere screenshots", true, false});
    app::ImGuiLayer ui(window.handle(), 1.0f);

    // A solved Cornell box and a point on its back wall, looking into the box and out of its open front.
    auto snapshot = std::make_shared<app::Snapshot>();
    snapshot->generation = 1;
    snapshot->meshGeneration = 1;
    snapshot->scene = std::make_shared<const Scene>(makeCornellBox());
    snapshot->mesh = std::make_shared<const PatchMesh>(meshScene(*snapshot->scene, MeshingOptions{0.005}));
    const std::unique_ptr<Solver> solver = makeSolver(SolverMethod::GaussSeidel, *snapshot->scene, *snapshot->mesh);
    for (int i = 0; i < 40 && solver->lastStats().residual > 1e-4; ++i) solver->step();
    snapshot->radiosity = solver->solution();
    const std::shared_ptr<const app::Snapshot> shown = snapshot;
    auto session = std::make_shared<app::HemicubeSession>(
        [shown] { return shown; },
        [] { return std::optional<app::HemicubePoint>(app::HemicubePoint{{0.278, 0.30, 0.5592}, {0, 0, -1}, 0}); });
    session->setResolution(256);
    app::HemispherePanel hemisphere(session);
    const auto view = [&](HemisphereProjection projection, render::HemisphereColouring colouring, const char* name) {
        hemisphere.setProjection(projection);
        hemisphere.setColouring(colouring);
        hemisphere.update();
        shoot(window, ui, [&] { hemisphere.draw(); }, "Hemisphere", dir / name);
    };
    view(HemisphereProjection::Nusselt, render::HemisphereColouring::Surfaces, "hemisphere-nusselt.png");
    view(HemisphereProjection::Equidistant, render::HemisphereColouring::Radiance, "hemisphere-fisheye-radiance.png");
    view(HemisphereProjection::Equisolid, render::HemisphereColouring::DeltaFormFactor, "hemisphere-delta-ff.png");

    app::IntegralsPanel integrals(session);
    integrals.select(app::HemisphereIntegrand::Irradiance, {app::IntegralMethod::CosineMonteCarlo, 16, 20000, 1});
    integrals.current().step(3000);
    shoot(window, ui, [&] { integrals.draw(); }, "Integrals", dir / "hemisphere-integrals.png");
    integrals.select(app::HemisphereIntegrand::ProjectedSolidAngle, {app::IntegralMethod::UniformMonteCarlo, 16, 20000, 1});
    integrals.current().step(20000);
    shoot(window, ui, [&] { integrals.draw(); }, "Integrals", dir / "hemisphere-integrals-uniform.png");
    integrals.select(app::HemisphereIntegrand::ProjectedSolidAngle, {app::IntegralMethod::Riemann, 8, 0, 1});
    integrals.current().step(integrals.current().total());
    shoot(window, ui, [&] { integrals.draw(); }, "Integrals", dir / "hemisphere-integrals-riemann.png");

    app::PointSourceDemo pointSource;
    pointSource.settings.offsetM = 1.5;
    shoot(window, ui, [&] { pointSource.draw(); }, pointSource.title(), dir / "demo-point-source.png");
    app::DiffuseEmitterDemo emitter;
    shoot(window, ui, [&] { emitter.draw(); }, emitter.title(), dir / "demo-diffuse-emitter.png");
    app::SunDemo sun;
    shoot(window, ui, [&] { sun.draw(); }, sun.title(), dir / "demo-sun.png", 620);
    app::SquareSolidAngleDemo square;
    square.settings.distanceM = 0.6;
    shoot(window, ui, [&] { square.draw(); }, square.title(), dir / "demo-square-solid-angle.png");
    app::DodecahedronDemo dodecahedron;
    shoot(window, ui, [&] { dodecahedron.draw(); }, dodecahedron.title(), dir / "demo-dodecahedron.png");
    app::RadianceIrradianceDemo radiance;
    shoot(window, ui, [&] { radiance.draw(); }, radiance.title(), dir / "demo-radiance-irradiance.png");
}

/// The Hemisphere panel in the lab, a floor point picked.
void labHemisphere(const std::filesystem::path& dir) {
    app::LabOptions options;
    options.maxPatchArea = 0.01;  // coarse: the default mesh's Gauss-Seidel matrix takes seconds
    options.width = 1400;
    options.height = 1000;
    options.vsync = false;
    app::Lab lab(options);
    for (int i = 0; i < 600 && !(lab.snapshot()->stats.iteration > 0 && !lab.snapshot()->running); ++i) lab.frame();
    if (lab.snapshot()->stats.iteration == 0) throw std::runtime_error("the lab did not solve");
    const glm::dvec3 floorPoint{0.42, 0.0, 0.12};
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), floorPoint);
    if (!lab.clickAt({pixel.x, pixel.y})) throw std::runtime_error("the floor point was not picked");
    lab.focusPanel("Hemisphere");
    render::ImageRgb8 image;
    for (int i = 0; i < 6; ++i) image = lab.frameAndCapture();
    render::writePng(image, dir / "hemisphere-lab.png");
    std::printf("wrote %s\n", (dir / "hemisphere-lab.png").string().c_str());
}

// The dome in the 3D view for the README: the solved Cornell box seen from above the front, a floor
// point between the blocks, the light outlined as the target.
void dome3d(const std::filesystem::path& dir) {
    const app::Window window({320, 240, "screenshots", false, false});
    const Scene box = makeCornellBox();
    const PatchMesh mesh = meshScene(box, MeshingOptions{0.005});
    const std::unique_ptr<Solver> solver = makeSolver(SolverMethod::GaussSeidel, box, mesh);
    for (int i = 0; i < 40 && solver->lastStats().residual > 1e-4; ++i) solver->step();
    const std::vector<Rgb> radiosity = solver->solution();

    const glm::dvec3 point{0.41, 0.0, 0.13}, up{0, 1, 0};
    render::HemicubeRenderer hemicube(mesh);
    const render::HemicubeCapture capture = hemicube.capture(point, up, 256);
    std::vector<glm::vec3> colours;
    for (const Surface& surface : box.surfaces) colours.push_back(render::displayColour(box.materials[surface.material]));
    const HemisphereViewMap map(capture.layout, HemisphereProjection::Equidistant, 512);
    render::HemisphereImageOptions look;
    look.grid = false;
    look.openSkyAlpha = 0;
    look.targetSurface = box.findSurface("light");
    render::HemisphereOverlay overlay;
    overlay.setImage(512, render::hemisphereImage(map, capture, mesh, colours, radiosity, look), std::numbers::pi / 2);
    overlay.setPlacement({point + up * 1e-4, capture.frame, 0.18 * 0.5592});
    overlay.setStyle({0.9f, true});

    render::PatchRenderer patches;
    patches.setMesh(box, mesh, 1);
    patches.setMaterials(box);
    patches.setRadiosity(radiosity, 1);
    patches.setSettings(render::DisplaySettings{});
    patches.prepare();
    render::Camera camera;
    camera.eye = {0.278, 0.50, -0.42};
    camera.forward = glm::normalize(glm::dvec3(0.33, 0.08, 0.20) - camera.eye);
    camera.fieldOfView = Radians(0.62);
    constexpr int kWidth = 1200, kHeight = 800;
    const PatchesUnderDome scene{patches, overlay};
    const std::filesystem::path file = dir / "hemisphere-3d.png";
    render::writePng(render::renderOffscreen(scene, camera, kWidth, kHeight, {0.075f, 0.08f, 0.09f}), file);
    std::printf("wrote %s\n", file.string().c_str());
}

/// Each lecture demo in the lab's 3D view, 1600 x 1000 at UI scale 1.5 (a projector), its section
/// open in the sidebar; the point-source demo with the pointer resting on the plane.
void demos3d(const std::filesystem::path& dir) {
    app::LabOptions options;
    options.maxPatchArea = 0.05;
    options.width = 1600;
    options.height = 1000;
    options.vsync = false;
    options.uiScale = 1.5f;
    options.runOnStart = false;
    app::Lab lab(options);
    for (int i = 0; i < 600 && !lab.snapshot()->mesh; ++i) lab.frame();
    for (const std::string& id : app::lesson::demoIds()) {
        lab.openDemo(id);
        for (int i = 0; i < 4; ++i) lab.frame();
        if (id == "point-source") {
            const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), {-2.6, 0.0, 1.6});
            lab.overrideMouse(glm::vec2(static_cast<float>(pixel.x), static_cast<float>(pixel.y)));
        }
        render::ImageRgb8 image;
        for (int i = 0; i < 4; ++i) image = lab.frameAndCapture();
        lab.overrideMouse(std::nullopt);
        const std::filesystem::path file = dir / ("demo-3d-" + id + ".png");
        render::writePng(image, file);
        std::printf("wrote %s\n", file.string().c_str());
    }
    lab.closeDemo();
}

} // namespace

int main(int argc, char** argv) {
    const std::filesystem::path dir = argc > 1 ? argv[1] : "docs/screenshots";
    try {
        std::filesystem::create_directories(dir);
        // A second argument "demos" takes the lecture demos' 3D pictures alone.
        const bool demosOnly = argc > 2 && std::string(argv[2]) == "demos";
        if (!demosOnly) {
            panels(dir);
            labHemisphere(dir);
            dome3d(dir);
        }
        demos3d(dir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiant_screenshots: %s\n", e.what());
        return 1;
    }
    return 0;
}
