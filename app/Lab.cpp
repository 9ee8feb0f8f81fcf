#include "app/Lab.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>

#include "app/panels/InfoPanel.h"
#include "app/ui/FrameStats.h"
#include "app/ui/ImGuiLayer.h"
#include "app/ui/Sidebar.h"
#include "app/window/CameraController.h"
#include "app/window/Window.h"
#include "radiometry/common/Error.h"
#include "app/panels/ScenePanel.h"
#include "radiometry/scene/SceneLibrary.h"
#include "render/FlatSceneRenderer.h"
#include "render/OffscreenRender.h"
#include "render/WireframeRenderer.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {
namespace {

// Behind the box: a dark neutral grey, so no colour competes with the walls' and the box's edges
// stay visible where they meet the background.
const glm::vec3 kBackground{0.075f, 0.08f, 0.09f};

constexpr double kDefaultMaxPatchArea = 0.01;  // m^2: 100 cm^2, a few hundred patches in the Cornell box

Scene openScene(const std::string& nameOrPath) {
    LoadedScene loaded = loadScene(nameOrPath);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
    return std::move(loaded.scene);
}

std::string windowTitle(const Scene& scene) {
    return "Radiant - " + std::filesystem::path(scene.name).filename().string();
}

void sceneBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    for (const Surface& surface : scene.surfaces)
        for (const Face& face : surface.faces)
            for (const glm::dvec3& v : face.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
}

render::OrbitCamera homeCamera(const Scene& scene) {
    glm::dvec3 lo, hi;
    sceneBounds(scene, lo, hi);
    const glm::dvec3 centre = (lo + hi) / 2.0;
    // The Cornell box has a published camera; other scenes are framed from their bounds.
    return render::OrbitCamera(scene.name == "cornell-box" ? render::cornellCamera() : render::framingCamera(lo, hi),
                               centre);
}

} // namespace

struct Lab::State {
    explicit State(const LabOptions& options)
        : scene(openScene(options.scene)),
          window({options.width, options.height, windowTitle(scene), options.visible, options.vsync}),
          gl(render::queryGlInfo()),
          orbit(homeCamera(scene)),
          panelsVisible(options.showPanels) {
        // Our key handler first: ImGui's backend installs its own and chains to this one.
        glfwSetWindowUserPointer(window.handle(), this);
        glfwSetKeyCallback(window.handle(), [](GLFWwindow* w, int key, int, int action, int) {
            if (action != GLFW_PRESS) return;
            auto* self = static_cast<State*>(glfwGetWindowUserPointer(w));
            if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
            self->onKey(key);
        });
        glfwSetDropCallback(window.handle(), [](GLFWwindow* w, int count, const char** paths) {
            auto* self = static_cast<State*>(glfwGetWindowUserPointer(w));
            if (count > 0 && self->scenePanel) self->scenePanel->open(paths[0]);  // one scene at a time
        });
        ui.emplace(window.handle(), options.uiScale);
        renderer = std::make_unique<render::FlatSceneRenderer>(scene);
        auto panel = std::make_unique<ScenePanel>(
            [this](const Scene& loaded, const PatchMesh& mesh) { install(loaded, mesh); }, scene,
            kDefaultMaxPatchArea);
        scenePanel = panel.get();
        sidebar.add(std::move(panel));
        sidebar.add(std::make_unique<InfoPanel>(frames, gl, window.fallbackNote(), *ui));
    }

    ~State() {
        wireframe.reset();
        renderer.reset();  // GL objects die while their context is alive
        ui.reset();
    }

    /// A new scene or a new mesh of this one, from the Scene panel's worker.
    void install(const Scene& loaded, const PatchMesh& mesh) {
        const bool sameScene = loaded.name == scene.name;
        scene = loaded;
        renderer = std::make_unique<render::FlatSceneRenderer>(scene);
        wireframe = std::make_unique<render::WireframeRenderer>(mesh);
        if (!sameScene) {
            orbit = homeCamera(scene);
            window.setTitle(windowTitle(scene));
        }
    }

    void onKey(int key) {
        if (key == GLFW_KEY_ESCAPE) window.requestClose();
        if (key == GLFW_KEY_C) orbit.reset();
        if (key == GLFW_KEY_H) panelsVisible = !panelsVisible;
    }

    void frame(render::ImageRgb8* capture) {
        const double now = glfwGetTime();
        if (lastFrameTime) frames.add(now - *lastFrameTime);
        lastFrameTime = now;

        glfwPollEvents();
        sidebar.update();
        ui->newFrame();
        int width = 0, height = 0;
        window.framebufferSize(width, height);
        const float pixelRatio = window.pixelRatio();

        const float sidebarWidth = panelsVisible ? sidebar.draw("Radiant", scene.name) : 0.0f;
        const int sidebarPixels = static_cast<int>(std::lround(sidebarWidth * pixelRatio));
        viewport = {sidebarPixels, 0, std::max(1, width - sidebarPixels), std::max(1, height)};
        const render::Viewport viewInUiUnits{static_cast<int>(sidebarWidth), 0,
                                             static_cast<int>(static_cast<float>(viewport.width) / pixelRatio),
                                             static_cast<int>(static_cast<float>(viewport.height) / pixelRatio)};
        controller.update(orbit, viewInUiUnits);

        lastCamera = orbit.camera();
        render::beginWindowFrame(width, height, viewport, kBackground);
        renderer->draw(lastCamera, viewport.aspect());
        if (wireframe && scenePanel->showWireframe()) wireframe->draw(lastCamera, viewport.aspect());
        render::useWholeWindow(width, height);
        ui->render();
        if (capture) *capture = render::readWindowPixels(width, height);
        window.swapBuffers();
    }

    Scene scene;
    Window window;
    render::GlInfo gl;
    render::OrbitCamera orbit;
    bool panelsVisible;
    std::optional<ImGuiLayer> ui;
    std::unique_ptr<render::SceneRenderer> renderer;
    std::unique_ptr<render::WireframeRenderer> wireframe;
    ScenePanel* scenePanel = nullptr;  // owned by the sidebar
    FrameStats frames;
    Sidebar sidebar;
    CameraController controller;
    std::optional<double> lastFrameTime;
    render::Viewport viewport;
    render::Camera lastCamera;
};

Lab::Lab(const LabOptions& options) : state_(std::make_unique<State>(options)) {}
Lab::~Lab() = default;

bool Lab::shouldClose() const { return state_->window.shouldClose(); }
void Lab::requestClose() { state_->window.requestClose(); }
void Lab::frame() { state_->frame(nullptr); }

render::ImageRgb8 Lab::frameAndCapture() {
    render::ImageRgb8 image;
    state_->frame(&image);
    return image;
}

render::ImageRgb8 Lab::renderOffscreen(int width, int height) const {
    return render::renderOffscreen(*state_->renderer, state_->orbit.camera(), width, height, kBackground);
}

render::Viewport Lab::sceneViewport() const { return state_->viewport; }
render::Camera Lab::camera() const { return state_->lastCamera; }
void Lab::resetCamera() { state_->orbit.reset(); }
const render::GlInfo& Lab::glInfo() const { return state_->gl; }
void Lab::setPanelsVisible(bool visible) { state_->panelsVisible = visible; }

} // namespace radiant::app
