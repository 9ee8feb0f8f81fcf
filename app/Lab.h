#pragma once
// The lab as an object the frame loop and the GL tests both drive: construct (opens the window and
// starts the solver thread), frame() as often as wanted, read frames back, destroy (closes the
// window). GL-free header.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/LabApp.h"
#include "app/lessons/LessonPlayer.h"
#include "app/solver/SolverCommand.h"
#include "app/solver/Comparison.h"
#include "app/solver/SolutionDifference.h"
#include "app/solver/Snapshot.h"
#include "radiometry/probe/Probe.h"
#include "render/DisplaySettings.h"
#include "render/GlContext.h"
#include "render/ImageRgb8.h"
#include "render/camera/Camera.h"

namespace radiant::app {

class IntegralsPanel;

class Lab {
public:
    /// Opens the window on `options.scene` and sends it to the solver thread. Throws RadiantError
    /// (no display, no GL 3.3, bad scene).
    explicit Lab(const LabOptions& options);
    ~Lab();
    Lab(const Lab&) = delete;
    Lab& operator=(const Lab&) = delete;

    [[nodiscard]] bool shouldClose() const;
    void requestClose();

    /// Handles input, takes the newest snapshot (never waits for the solver), draws one frame and
    /// shows it.
    void frame();
    /// As frame(), but first sleeps until input arrives (at most `maxWaitSeconds` while a panel
    /// refines unprompted, the probe's path tracer; 4x that otherwise) when nothing on screen can
    /// change: the window's loop, so an idle lab leaves the CPU alone.
    void frameWhenNeeded(double maxWaitSeconds = 0.5);
    /// True while frames can show something new without input (see frameWhenNeeded).
    [[nodiscard]] bool changing() const;
    /// Tests: the pointer at a point of the window (ImGui coordinates, top-left origin) with the left
    /// button up or down, in place of the real pointer, from the next frame; nullopt gives it back.
    void overrideMouse(std::optional<glm::vec2> windowPoint, bool leftDown = false);
    /// As frame(), and returns the framebuffer as drawn (panels included when shown), top row first.
    render::ImageRgb8 frameAndCapture();

    /// The 3D view alone, drawn with the current camera into an offscreen width x height image.
    [[nodiscard]] render::ImageRgb8 renderOffscreen(int width, int height) const;

    /// The 3D view's rectangle in framebuffer pixels during the last frame (top-left origin).
    [[nodiscard]] render::Viewport sceneViewport() const;
    /// The camera the last frame was drawn with.
    [[nodiscard]] render::Camera camera() const;
    /// Back to the scene's home view (key C): the Cornell camera for the Cornell box.
    void resetCamera();
    [[nodiscard]] const render::GlInfo& glInfo() const;
    void setPanelsVisible(bool visible);

    /// Snapshots whose radiosity the renderer took (each a recolouring and upload).
    [[nodiscard]] std::uint64_t radiosityUploads() const;
    /// Frames drawn since the window opened.
    [[nodiscard]] std::uint64_t frameCount() const;
    /// The snapshot the last frame drew.
    [[nodiscard]] std::shared_ptr<const Snapshot> snapshot() const;
    /// Sends a command to the solver thread, as the panels do.
    void send(SolverCommand command);
    /// A key press as the keyboard gives it (GLFW key code): the shortcuts listed in the Info panel.
    void pressKey(int glfwKey, bool control = false);
    /// A left click at a framebuffer pixel (top-left origin), as a mouse click in the 3D view: picks
    /// the probe point. False when the ray hits nothing.
    bool clickAt(const glm::dvec2& framebufferPixel);
    /// The probe's picked point (m) from the moment a click is taken; its reading follows later.
    [[nodiscard]] std::optional<glm::dvec3> probePoint() const;
    /// The probe's newest reading and the snapshot generation it was measured on (0: none yet).
    [[nodiscard]] std::optional<ProbeReading> probeReading() const;
    [[nodiscard]] std::uint64_t probeGeneration() const;
    /// A material edit through the Materials panel's path; returns why it was refused, or empty.
    std::string editMaterial(std::size_t surface, const Rgb& reflectance, const Rgb& exitanceW_m2);
    [[nodiscard]] render::DisplaySettings& display();
    /// The status bar's last message (e.g. where F12 saved the screenshot).
    [[nodiscard]] std::string statusMessage() const;
    /// Shows only the named panel expanded (screenshots of one panel); empty expands them all.
    void focusPanel(const std::string& title);
    /// Reads a lesson file and goes to its first step; throws RadiantError (one line) on a bad file,
    /// leaving the lab as it was.
    void openLesson(const std::string& file);
    /// The open lesson, its step and whether the step's actions have all run.
    [[nodiscard]] const LessonPlayer& lessons() const;
    /// Saves the lab's state as a session file (Ctrl+S; SessionFile.h) to `file`, or to a dated
    /// name in the working folder when empty; returns the path. Throws RadiantError when it cannot.
    std::filesystem::path saveSession(const std::string& file = "");
    /// Tests: blocks until the solver thread has applied every command sent and stopped running.
    void waitForSolver();
    /// Comparison mode (two methods side by side, app/solver/Comparison.h): on or off (key V cycles
    /// off, side by side, difference), B's method, meshing and the view.
    void compare(bool on);
    void setComparison(const ComparisonSettings& settings);
    /// B's settings, or nullopt while the comparison is off.
    [[nodiscard]] std::optional<ComparisonSettings> comparison() const;
    /// B's snapshot the last frame drew; null while the comparison is off.
    [[nodiscard]] std::shared_ptr<const Snapshot> secondSnapshot() const;
    /// The difference view's values as last computed (mesh null: none yet).
    [[nodiscard]] const SolutionDifference& comparisonDifference() const;
    /// Where the last frame drew the 3D view, in framebuffer pixels: one viewport, or A's half and B's.
    [[nodiscard]] std::vector<render::Viewport> sceneViews() const;
    /// The probe's reading of solution B at the picked point (comparison mode), as probeReading() of A.
    [[nodiscard]] std::optional<ProbeReading> secondProbeReading() const;
    /// Shows a lecture demo (lesson::demoIds(): "point-source", ...) in the 3D view, its section open
    /// in the sidebar, the scene's camera put aside; an unknown id does nothing.
    void openDemo(const std::string& id);
    /// Back to the scene, its camera as it was (the solve and the probe were never touched).
    void closeDemo();
    /// The id of the demo the 3D view shows, or empty.
    [[nodiscard]] std::string activeDemo() const;
    /// The last lesson action the lab refused (empty: none), also shown in the status bar.
    [[nodiscard]] std::string lessonError() const;
    /// The framebuffer row (from the top) where the open lesson's caption band begins, as of the
    /// last frame: the 3D view (sceneViewport) ends there. None without a lesson caption.
    [[nodiscard]] std::optional<int> lessonCaptionTop() const;
    /// The Integrals panel: its integrand, estimator and run (a lesson's "integrals" action sets them).
    [[nodiscard]] const IntegralsPanel& integrals() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace radiant::app
