#pragma once
// The lab as an object the frame loop and the GL tests both drive: construct (opens the window),
// frame() as often as wanted, read frames back, destroy (closes the window). GL-free header.
#include <memory>

#include "app/LabApp.h"
#include "render/GlContext.h"
#include "render/ImageRgb8.h"
#include "render/camera/Camera.h"

namespace radiant::app {

class Lab {
public:
    /// Opens the window on `options.scene`. Throws RadiantError (no display, no GL 3.3, bad scene).
    explicit Lab(const LabOptions& options);
    ~Lab();
    Lab(const Lab&) = delete;
    Lab& operator=(const Lab&) = delete;

    [[nodiscard]] bool shouldClose() const;
    void requestClose();

    /// Handles input, draws one frame and shows it.
    void frame();
    /// As frame(), and returns the framebuffer as drawn (panels included when shown), top row first.
    render::ImageRgb8 frameAndCapture();

    /// The 3D view alone, drawn with the current camera into an offscreen width x height image.
    [[nodiscard]] render::ImageRgb8 renderOffscreen(int width, int height) const;

    /// The 3D view's rectangle in framebuffer pixels during the last frame (top-left origin).
    [[nodiscard]] render::Viewport sceneViewport() const;
    /// The camera the last frame was drawn with.
    [[nodiscard]] render::Camera camera() const;
    /// Back to the Cornell camera (key C).
    void resetCamera();
    [[nodiscard]] const render::GlInfo& glInfo() const;
    void setPanelsVisible(bool visible);

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace radiant::app
