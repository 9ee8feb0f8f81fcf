#include "app/Lab.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/panels/DisplayPanel.h"
#include "app/panels/HemicubeSession.h"
#include "app/panels/HemispherePanel.h"
#include "app/lessons/Lesson.h"
#include "app/LabComparison.h"
#include "app/LabLessonStage.h"
#include "app/LabScene.h"
#include "app/SnapshotToRenderer.h"
#include "app/lessons/LessonCaption.h"
#include "app/lessons/SessionFile.h"
#include "app/panels/InfoPanel.h"
#include "app/panels/LessonsPanel.h"
#include "app/panels/IntegralsPanel.h"
#include "app/panels/demos/DemoView.h"
#include "app/panels/demos/LectureDemosPanel.h"
#include "app/panels/MaterialsPanel.h"
#include "app/panels/ProbePanel.h"
#include "app/panels/ScenePanel.h"
#include "app/panels/SolverPanel.h"
#include "app/solver/ConvergenceQuantity.h"
#include "app/solver/LiveSolve.h"
#include "app/solver/MethodLabel.h"
#include "app/solver/SolverThread.h"
#include "app/ui/DemoPicture.h"
#include "app/ui/FrameStats.h"
#include "app/ui/ImGuiLayer.h"
#include "app/ui/LegendOverlay.h"
#include "app/ui/ProbeMarker.h"
#include "app/ui/Shortcuts.h"
#include "app/ui/Sidebar.h"
#include "app/ui/StatusBar.h"
#include "app/ui/Theme.h"
#include "app/window/CameraController.h"
#include "app/window/PickRay.h"
#include "app/window/Window.h"
#include "radiometry/common/Error.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/View.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/Screenshot.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {
namespace {

// Behind the box and the panels alike (app/ui/Theme.h): a dark neutral grey, so no colour competes
// with the walls' and the box's edges stay visible where they meet the background.
const glm::vec3 kClearColour{kBackdrop.r, kBackdrop.g, kBackdrop.b};

std::string sceneLabel(const std::string& sceneName) { return std::filesystem::path(sceneName).filename().string(); }

std::string windowTitle(const std::string& sceneName, SolverMethod method) {
    return "Radiant - " + sceneLabel(sceneName) + " - " + methodLabel(method);
}

} // namespace

struct Lab::State {
    explicit State(const LabOptions& options)
        : initialScene(openScene(options.scene)),
          window({options.width, options.height, windowTitle(initialScene->name, kSolveDefaults.method),
                  options.visible, options.vsync}),
          gl(render::queryGlInfo()),
          orbit(orbitFromHome(*initialScene, nullptr)),
          panelsVisible(options.showPanels),
          live(solverThread),
          patchArea(options.maxPatchArea.value_or(kSolveDefaults.maxPatchArea)) {
        display.uiScale = options.uiScale;
        // Our callbacks first: ImGui's backend installs its own and chains to these.
        glfwSetWindowUserPointer(window.handle(), this);
        glfwSetKeyCallback(window.handle(), [](GLFWwindow* w, int key, int, int action, int mods) {
            auto* self = static_cast<State*>(glfwGetWindowUserPointer(w));
            if (action == GLFW_PRESS && self->ui) self->ui->notePress(key);
            if (action == GLFW_RELEASE) return;
            // Typing into a field, or a slider being dragged, keeps its keys; a panel merely
            // clicked does not (the lecturer's presenter sends Space and Page Down whatever was
            // clicked last).
            if (ImGuiLayer::keyboardClaimed()) return;
            const std::optional<Shortcut> shortcut = shortcutForKey(key, (mods & GLFW_MOD_CONTROL) != 0);
            if (!shortcut || (action == GLFW_REPEAT && !shortcut->repeats)) return;
            self->onAction(shortcut->action);
        });
        // The pointer and the buttons in event order, so a click is taken where it happened, not
        // where a slow frame finds the pointer (ButtonEvents.h). ImGui's backend chains to the
        // button callback and installs no cursor-position callback of its own.
        glfwSetCursorPosCallback(window.handle(), [](GLFWwindow* w, double x, double y) {
            static_cast<State*>(glfwGetWindowUserPointer(w))->buttons.moved({x, y});
        });
        glfwSetMouseButtonCallback(window.handle(), [](GLFWwindow* w, int button, int action, int) {
            auto* self = static_cast<State*>(glfwGetWindowUserPointer(w));
            if (!self->buttons.knowsPointer()) {  // pressed before any motion reached the window
                double x = 0, y = 0;
                glfwGetCursorPos(w, &x, &y);
                self->buttons.moved({x, y});
            }
            self->buttons.button(button, action == GLFW_PRESS);
        });
        glfwSetDropCallback(window.handle(), [](GLFWwindow* w, int count, const char** paths) {
            auto* self = static_cast<State*>(glfwGetWindowUserPointer(w));
            if (count > 0 && self->scenePanel) self->scenePanel->open(paths[0]);  // one scene at a time
        });
        ui.emplace(window.handle(), options.uiScale);
        patches.emplace();
        comparison.emplace(live);
        demoRenderer.emplace();

        auto scene = std::make_unique<ScenePanel>(live, options.maxPatchArea);
        const double openingArea = scene->patchAreaFor(*initialScene);
        scenePanel = scene.get();
        auto probe = std::make_unique<ProbePanel>(live);
        probe->followUnits(display);
        probePanel = probe.get();
        sidebar.add(std::move(scene));
        sidebar.add(std::make_unique<SolverPanel>(live));
        sidebar.add(std::make_unique<MaterialsPanel>(live, [this] { return probePanel->picked(); }));
        sidebar.add(std::move(probe));
        sidebar.add(std::make_unique<DisplayPanel>(display, [this] { return patches->legend(); }));
        sidebar.add(std::make_unique<InfoPanel>(frames, gl, window.fallbackNote()));
        // The hemicube over the probe's pick, shared by the Hemisphere and Integrals panels.
        auto hemicube = std::make_shared<HemicubeSession>(
            [this] { return live.current; },
            [this]() -> std::optional<HemicubePoint> {
                const std::optional<ProbePick>& pick = probePanel->picked();
                if (!pick || pick->meshGeneration != live.snapshot().meshGeneration) return std::nullopt;
                return HemicubePoint{pick->point, pick->normal, pick->surface};
            });
        auto hemisphere = std::make_unique<HemispherePanel>(hemicube);
        hemispherePanel = hemisphere.get();
        sidebar.add(std::move(hemisphere));
        auto integrals = std::make_unique<IntegralsPanel>(hemicube);
        integralsPanel = integrals.get();
        sidebar.add(std::move(integrals));
        auto demos = std::make_unique<LectureDemosPanel>(demoView);
        demosPanel = demos.get();
        sidebar.add(std::move(demos));
        auto lessonList = std::make_unique<LessonsPanel>(lessons, [this](const std::string& file) -> std::string {
            try {
                openLesson(file);
                return "";
            } catch (const RadiantError& error) {
                return error.what();
            }
        });
        lessonsPanel = lessonList.get();
        sidebar.add(std::move(lessonList));
        stage.emplace(live, sidebar, *demosPanel, *probePanel, *integralsPanel, orbit, display, patchArea);

        live.send(command::LoadScene{initialScene, MeshingOptions{openingArea}});
        if (options.runOnStart) live.send(command::Run{});
    }

    ~State() {
        comparison->release();  // GL objects die while their context is alive
        patches.reset();
        demoRenderer.reset();
        ui.reset();
    }

    void onAction(LabAction action) {
        switch (action) {
        case LabAction::Quit: window.requestClose(); break;
        case LabAction::RunPause:
            live.send(live.running() ? SolverCommand{command::Pause{}} : SolverCommand{command::Run{}});
            break;
        case LabAction::Compare: comparison->cycle(); break;
        case LabAction::Step: live.send(command::Step{1}); break;
        case LabAction::Reset: live.send(command::Reset{}); break;
        case LabAction::Rekey: DisplayPanel::rekey(display); break;
        case LabAction::FalseColour:
            display.colourMode = display.colourMode == render::ColourMode::FalseColour ? render::ColourMode::ToneMapped
                                                                                      : render::ColourMode::FalseColour;
            break;
        case LabAction::Wireframe: display.wireframe = !display.wireframe; break;
        case LabAction::HomeView: orbit.reset(); break;
        case LabAction::TogglePanels: panelsVisible = !panelsVisible; break;
        case LabAction::Dome: hemispherePanel->setOverlayShown(!hemispherePanel->overlayShown()); break;
        case LabAction::NextLessonStep: lessons.next(); break;
        case LabAction::PreviousLessonStep: lessons.previous(); break;
        case LabAction::SaveSession:
            try {
                message = "saved the session as " + saveSession("").string();
            } catch (const std::exception& e) {
                message = std::string("the session was not saved: ") + e.what();
            }
            break;
        case LabAction::OpenFile:
            lessonsPanel->focusPath();
            sidebar.focus("Lessons");
            break;
        case LabAction::UndoMaterial:
        case LabAction::RedoMaterial: {
            const bool undoing = action == LabAction::UndoMaterial;
            const std::string done = undoing ? MaterialsPanel::undo(live) : MaterialsPanel::redo(live);
            message = done.empty() ? std::string(undoing ? "no material edit to undo" : "no material edit to redo") : done;
            break;
        }
        case LabAction::Screenshot: screenshotRequested = true; break;
        }
    }

    /// Hands the newest snapshot to the renderer: each upload happens only when its generation moved.
    void stream() {
        live.refresh();
        const Snapshot& s = live.snapshot();
        if (!s.scene || !s.mesh) return;
        // A's renderer takes A's solutions only while they are on screen: the difference view hides
        // them, and each would cost a pass over A's patches (in false colour the Display panel
        // still shows A's legend: taken then). The frame the difference goes (a new mesh, the view
        // switched back), A catches up before it is drawn.
        const bool firstHidden = comparison->hidesFirst() && display.colourMode != render::ColourMode::FalseColour;
        if (!firstHidden) streamSnapshotToRenderer(s, *patches, materialsShown);
        comparison->stream(display, *patches);
        if (firstHidden && !comparison->hidesFirst()) streamSnapshotToRenderer(s, *patches, materialsShown);
        if (s.scene->name != sceneShown) {
            // The home view casts with the scene's one ray caster, which the solver thread builds
            // (the window's first frames used the outside framing meanwhile).
            demoView.sceneCamera() = orbitFromHome(*s.scene, s.rays.get());  // not a demo's camera
            viewSent.reset();  // the solver thread forgot the old scene's camera
            sceneShown = s.scene->name;
        }
        const std::string title = windowTitle(s.scene->name, s.method);
        if (title != titleShown) {
            window.setTitle(title);
            titleShown = title;
        }
    }

    StatusLine status() const {
        StatusLine line;
        const Snapshot& s = live.snapshot();
        const SolverActivity activity = solverThread.activity();
        if (scenePanel->loading()) {
            line.activity = "loading scene";
        } else if (activity == SolverActivity::Meshing || activity == SolverActivity::FormFactors) {
            line.activity = std::string(activityName(activity));
            line.fraction = solverThread.progress().fraction();
        }
        char text[320];
        if (s.stats.iteration == 0 && !s.methodReason.empty()) {
            // The default by size: the size here, the whole reason in the Solver panel (a line
            // that wraps over the picture's bottom is too much for a status strip).
            const std::string size = s.methodReason.substr(0, s.methodReason.find(':'));
            std::snprintf(text, sizeof text, "%s (default for %s; why: Solver panel) - %s", methodLabel(s.method),
                          size.c_str(), s.running ? "starting" : "ready");
        }
        else if (s.stats.iteration == 0)
            std::snprintf(text, sizeof text, "%s - %s", methodLabel(s.method), s.running ? "starting" : "ready");
        else
            // Each method's own measure by its name (ConvergenceQuantity.h), as the plot's axis says.
            std::snprintf(text, sizeof text, "%s - iteration %zu - %s %.2e%s", methodLabel(s.method),
                          s.stats.iteration, std::string(convergenceQuantity(s.method).name).c_str(),
                          s.stats.residual, s.running ? " - running" : "");
        line.solve = text;
        line.message = message;
        return line;
    }

    bool pickAt(const glm::dvec2& framebufferPixel) {
        render::Viewport half = viewport;  // the half the click fell in, when the view is split
        for (const render::Viewport& v : comparison->views(viewport))
            if (framebufferPixel.x >= v.x && framebufferPixel.x < v.x + v.width) half = v;
        const PickRay ray = pickRay(lastCamera, half, framebufferPixel);
        return probePanel->pick(ray.origin, ray.direction);
    }

    /// Tells the solver thread where the probe stands whenever the pick changes, so the snapshots
    /// single out the hierarchical links that point gathers through.
    void followPick() {
        const std::optional<ProbePick>& pick = probePanel->picked();
        std::optional<command::FocusedPoint> focus;
        if (pick) focus = command::FocusedPoint{pick->surface, pick->face, pick->point, pick->meshGeneration};
        if (focus == focusSent) return;
        live.send(command::FocusPoint{focus});
        focusSent = focus;
    }

    /// True while the picture can change without input: a solve running or being built, a newer
    /// snapshot not shown yet, a panel's background work or animation, or input moments ago (ImGui
    /// settles hover and the camera glides over the next frames).
    bool changing() const {
        const Snapshot& shown = live.snapshot();
        if (shown.running || solverThread.activity() != SolverActivity::Idle) return true;
        if (solverThread.snapshot()->generation != shown.generation) return true;
        if (live.secondChanging()) return true;  // comparison mode: B still solving, or newer
        if (sidebar.busy() || screenshotRequested) return true;
        return glfwGetTime() - lastInput < kAwakeAfterInput;
    }

    /// Sleeps until an event arrives (or `maxSeconds`, for work that posts none) when nothing on
    /// screen can change: a converged, untouched lab must not keep a core busy redrawing it.
    void waitWhileIdle(double maxSeconds) {
        if (changing()) return;
        // Nothing refining unprompted (the path tracer): wake seldom. Each wake-up draws a frame
        // (~40 ms of llvmpipe CPU at 1600 x 1000), and two a second kept a converged lab at 7.5% of
        // a core (`radiant bench --only frames`, 2026-12-02).
        const double timeout = sidebar.refreshesUnprompted() ? maxSeconds : kIdleWakeFactor * maxSeconds;
        const double before = glfwGetTime();
        glfwWaitEventsTimeout(timeout);
        const double after = glfwGetTime();
        if (after - before < 0.9 * timeout) lastInput = after;  // woken by an event, not the timeout
        lastFrameTime.reset();  // a wait is not a slow frame
    }

    void frame(render::ImageRgb8* capture) {
        const double now = glfwGetTime();
        if (lastFrameTime) frames.add(now - *lastFrameTime);
        lastFrameTime = now;

        glfwPollEvents();
        stream();
        if (display.uiScale > 0 && display.uiScale != ui->uiScale()) ui->setUiScale(display.uiScale);
        sidebar.update();
        if (std::optional<std::string> refused = lessons.update(*stage)) {
            lessonError = *refused;
            message = *refused;
        }
        ui->newFrame();
        int width = 0, height = 0;
        window.framebufferSize(width, height);
        const float pixelRatio = window.pixelRatio();

        const float sidebarWidth = panelsVisible ? sidebar.draw("Radiant", sceneLabel(sceneShown)) : 0.0f;
        const int sidebarPixels = static_cast<int>(std::lround(sidebarWidth * pixelRatio));
        // Right of the sidebar, the whole window's height: the status bar lies over the picture's
        // bottom edge, translucent; a lesson's caption takes a band of its own below the picture.
        const render::Viewport wholeView{static_cast<int>(sidebarWidth), 0,
                                         static_cast<int>(static_cast<float>(std::max(1, width - sidebarPixels)) / pixelRatio),
                                         static_cast<int>(static_cast<float>(std::max(1, height)) / pixelRatio)};
        const float statusHeight = panelsVisible ? drawStatusBar(wholeView, status()) : 0.0f;
        render::Viewport aboveStatus = wholeView;
        aboveStatus.height = std::max(1, aboveStatus.height - static_cast<int>(std::ceil(statusHeight)));
        const float captionBand = drawLessonCaption(lessons, aboveStatus);
        const int belowPicture = captionBand > 0.0f ? static_cast<int>(std::ceil(statusHeight + captionBand)) : 0;
        render::Viewport viewInUiUnits = wholeView;
        viewInUiUnits.height = std::max(1, wholeView.height - belowPicture);
        captionTop = captionBand > 0.0f ? std::optional<int>(static_cast<int>(std::lround(static_cast<float>(viewInUiUnits.height) * pixelRatio)))
                                        : std::nullopt;
        viewport = {sidebarPixels, 0, std::max(1, width - sidebarPixels),
                    std::max(1, captionTop ? *captionTop : height)};
        // Folding the demos' header away (sidebar shown) closes the demo, as closing its section does.
        if (panelsVisible && demoView.active() && !demosPanel->drawn()) demosPanel->closeDemo();
        const LectureDemo* demo = demoView.active();
        controller.update(orbit, viewInUiUnits, buttons.take());
        // A demo framed wider than the view is shown, picked and reported through a wider field.
        lastCamera = demoView.shownCamera(orbit.camera(), viewport.aspect());
        if (!demo) sendViewWhenStill(now);  // a demo's camera is not the scene's: importance keeps the scene's
        if (const std::optional<glm::dvec2> click = controller.click(); click && !demo)
            pickAt(*click * static_cast<double>(pixelRatio));
        followPick();
        if (!demo && !comparison->drawOverlays(viewInUiUnits) && display.colourMode == render::ColourMode::FalseColour)
            drawLegendOverlay(patches->legend(), viewInUiUnits);

        render::beginWindowFrame(width, height, viewport, kClearColour);
        if (demo) {
            drawDemoPicture(*demo, *demoRenderer, lastCamera, viewport, pixelRatio, ui->uiScale());
        } else {
            comparison->draw(*patches, display, lastCamera, viewport, height);  // leaves the viewport on A
            const std::vector<render::Viewport> views = comparison->views(viewport);
            if (const std::optional<ProbePick>& pick = probePanel->picked())  // before other overlays: only the scene hides it
                for (const render::Viewport& v : views) drawProbeMarker(lastCamera, v, height, pixelRatio, pick->point);
            hemispherePanel->drawOverlay(lastCamera, views.front().aspect());  // the sky of the probe point, over A
        }
        render::useWholeWindow(width, height);
        ui->render();
        if (capture || screenshotRequested) {
            render::ImageRgb8 image = render::readWindowPixels(width, height);
            if (screenshotRequested) saveScreenshot(image);
            if (capture) *capture = std::move(image);
        }
        window.swapBuffers();
        ++frameCount;
    }

    /// Importance-driven radiosity refines for the camera: each view it rests at (not every frame
    /// of a drag, which would restart the refinement each time) goes to the solver thread.
    void sendViewWhenStill(double now) {
        const View view = render::viewFromCamera(lastCamera, comparison->views(viewport).front().aspect());
        const auto same = [](const View& a, const View& b) {
            return a.eye == b.eye && a.target == b.target && a.up == b.up && a.verticalFov == b.verticalFov &&
                   a.aspect == b.aspect;
        };
        if (!viewMoving || !same(view, *viewMoving)) {
            viewMoving = view;
            viewMovedAt = now;
            return;
        }
        if (now - viewMovedAt < kCameraRestSeconds || (viewSent && same(view, *viewSent))) return;
        live.send(command::SetView{view});
        viewSent = view;
    }

    void openLesson(const std::string& file) {
        lessons.open(lesson::readLesson(file));  // reads and checks it all first: a bad file changes nothing
        lessonError.clear();
    }

    /// Writes the lab's state as a session file (SessionFile.h): to `path`, or when it is empty to
    /// radiant-session-YYYYMMDD-HHMMSS.json in the working folder. Returns where it went.
    std::filesystem::path saveSession(const std::string& path) {
        std::optional<std::string> target;
        if (const std::optional<ProbeReading>& reading = probePanel->reading(); reading && reading->target)
            target = reading->target->name;
        return lesson::writeSession(
            lesson::captureSession(live.snapshot(), demoView.sceneCamera().camera(), demoView.sceneCamera().pivot(),
                                   probePanel->picked(), target, display,
                                   live.comparing() ? std::optional(live.comparison()) : std::nullopt),
            path);
    }

    void saveScreenshot(const render::ImageRgb8& image) {
        screenshotRequested = false;
        try {
            message = "saved " + render::saveScreenshot(image).string();
        } catch (const std::exception& e) {
            message = std::string("screenshot failed: ") + e.what();
        }
    }

    std::shared_ptr<const Scene> initialScene;
    Window window;
    render::GlInfo gl;
    render::OrbitCamera orbit;
    DemoView demoView{orbit};  ///< puts the scene's camera aside while a lecture demo has the 3D view
    bool panelsVisible;
    SolverThread solverThread;
    LiveSolve live;
    render::DisplaySettings display;
    std::optional<ImGuiLayer> ui;
    std::optional<render::PatchRenderer> patches;
    std::optional<LabComparison> comparison;  ///< made with the renderer, released before it
    std::optional<render::DemoRenderer> demoRenderer;
    std::shared_ptr<const Scene> materialsShown;
    std::string sceneShown;
    std::string titleShown;
    ScenePanel* scenePanel = nullptr;  // owned by the sidebar
    ProbePanel* probePanel = nullptr;  // owned by the sidebar
    HemispherePanel* hemispherePanel = nullptr;  // owned by the sidebar
    IntegralsPanel* integralsPanel = nullptr;    // owned by the sidebar
    LectureDemosPanel* demosPanel = nullptr;  // owned by the sidebar
    LessonsPanel* lessonsPanel = nullptr;     // owned by the sidebar
    double patchArea;  ///< m^2: what the lab meshes a lesson's scenes with (the default, not the opening scene's)
    LessonPlayer lessons;
    std::optional<LabLessonStage> stage;  ///< made once the panels it drives exist
    std::string lessonError;
    std::optional<int> captionTop;  ///< framebuffer row where the lesson caption's band begins; none without a caption
    FrameStats frames;
    Sidebar sidebar;
    CameraController controller;
    ButtonRecorder buttons;  ///< fed by the window's callbacks, taken by `controller` once a frame
    std::optional<double> lastFrameTime;
    render::Viewport viewport;
    render::Camera lastCamera;
    bool screenshotRequested = false;
    std::optional<command::FocusedPoint> focusSent;
    static constexpr double kCameraRestSeconds = 0.3;
    std::optional<View> viewMoving, viewSent;
    double viewMovedAt = 0;
    std::string message;
    std::uint64_t frameCount = 0;
    /// How long frames keep coming after the last input event (s).
    static constexpr double kAwakeAfterInput = 0.5;
    /// Without unprompted refinement the idle wait is this many times frameWhenNeeded's: a missed
    /// wake-up (a command taken after the last frame) shows at most 2 s late.
    static constexpr double kIdleWakeFactor = 4.0;
    double lastInput = 0;  ///< glfwGetTime() of the last event that woke an idle wait
};

Lab::Lab(const LabOptions& options) : state_(std::make_unique<State>(options)) {}
Lab::~Lab() = default;

bool Lab::shouldClose() const { return state_->window.shouldClose(); }
void Lab::requestClose() { state_->window.requestClose(); }
void Lab::frame() { state_->frame(nullptr); }
void Lab::frameWhenNeeded(double maxWaitSeconds) {
    state_->waitWhileIdle(maxWaitSeconds);
    state_->frame(nullptr);
}
bool Lab::changing() const { return state_->changing(); }
void Lab::overrideMouse(std::optional<glm::vec2> windowPoint, bool leftDown) {
    if (windowPoint)
        state_->ui->overrideMouse(ImGuiLayer::MouseOverride{windowPoint->x, windowPoint->y, leftDown});
    else
        state_->ui->overrideMouse(std::nullopt);
}

render::ImageRgb8 Lab::frameAndCapture() {
    render::ImageRgb8 image;
    state_->frame(&image);
    return image;
}

render::ImageRgb8 Lab::renderOffscreen(int width, int height) const {
    return render::renderOffscreen(*state_->patches, state_->orbit.camera(), width, height, kClearColour);
}

render::Viewport Lab::sceneViewport() const { return state_->viewport; }
render::Camera Lab::camera() const { return state_->lastCamera; }
void Lab::resetCamera() { state_->orbit.reset(); }
const render::GlInfo& Lab::glInfo() const { return state_->gl; }
void Lab::setPanelsVisible(bool visible) { state_->panelsVisible = visible; }
std::uint64_t Lab::frameCount() const { return state_->frameCount; }
std::uint64_t Lab::radiosityUploads() const { return state_->patches->radiosityUploads(); }
std::shared_ptr<const Snapshot> Lab::snapshot() const { return state_->live.current; }
void Lab::send(SolverCommand command) { state_->live.send(std::move(command)); }
void Lab::pressKey(int glfwKey, bool control) {
    if (const std::optional<Shortcut> shortcut = shortcutForKey(glfwKey, control)) state_->onAction(shortcut->action);
}
bool Lab::clickAt(const glm::dvec2& framebufferPixel) { return state_->pickAt(framebufferPixel); }
std::optional<glm::dvec3> Lab::probePoint() const {
    const std::optional<ProbePick>& pick = state_->probePanel->picked();
    return pick ? std::optional(pick->point) : std::nullopt;
}
std::optional<ProbeReading> Lab::probeReading() const { return state_->probePanel->reading(); }
std::uint64_t Lab::probeGeneration() const { return state_->probePanel->readingGeneration(); }
std::string Lab::editMaterial(std::size_t surface, const Rgb& reflectance, const Rgb& exitanceW_m2) {
    return MaterialsPanel::submit(state_->live, surface, reflectance, exitanceW_m2);
}
render::DisplaySettings& Lab::display() { return state_->display; }
std::string Lab::statusMessage() const { return state_->message; }
void Lab::focusPanel(const std::string& title) { state_->sidebar.focus(title); }
void Lab::openLesson(const std::string& file) { state_->openLesson(file); }
const LessonPlayer& Lab::lessons() const { return state_->lessons; }
std::string Lab::lessonError() const { return state_->lessonError; }
std::optional<int> Lab::lessonCaptionTop() const { return state_->captionTop; }
const IntegralsPanel& Lab::integrals() const { return *state_->integralsPanel; }
std::filesystem::path Lab::saveSession(const std::string& file) { return state_->saveSession(file); }
void Lab::waitForSolver() { state_->solverThread.waitUntilIdle(); }
void Lab::compare(bool on) { state_->live.compare(on); }
void Lab::setComparison(const ComparisonSettings& settings) { state_->live.setComparison(settings); }
std::optional<ComparisonSettings> Lab::comparison() const {
    return state_->live.comparing() ? std::optional(state_->live.comparison()) : std::nullopt;
}
std::shared_ptr<const Snapshot> Lab::secondSnapshot() const { return state_->live.secondCurrent; }
const SolutionDifference& Lab::comparisonDifference() const { return state_->comparison->difference(); }
std::vector<render::Viewport> Lab::sceneViews() const { return state_->comparison->views(state_->viewport); }
std::optional<ProbeReading> Lab::secondProbeReading() const { return state_->probePanel->secondReading(); }
void Lab::openDemo(const std::string& id) { state_->stage->openDemo(id); }
void Lab::closeDemo() { state_->demosPanel->closeDemo(); }
std::string Lab::activeDemo() const {
    const LectureDemo* demo = state_->demoView.active();
    return demo ? demo->id() : "";
}

} // namespace radiant::app
