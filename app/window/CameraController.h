#pragma once
// Mouse gestures to orbit-camera motions, read from ImGui's input state each frame: drags that
// start over a panel belong to the panel (ImGui's WantCaptureMouse), drags that start in the 3D
// view move the camera until the button is released. Where a press and a release happened comes
// from the window's event record (ButtonEvents.h) when it has them, not from the pointer at frame time.
#include <optional>

#include <glm/vec2.hpp>

#include "app/window/ButtonEvents.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {

class CameraController {
public:
    /// Call between ImGui's NewFrame and Render. `view` is the 3D view in ImGui coordinates
    /// (top-left origin); `pixelRatio` converts none of it: gestures are scaled by the view's size.
    /// `events`: the buttons' presses and releases since the last update (ButtonRecorder::take());
    /// a button ImGui saw pressed with no event recorded (a test's overridden mouse) is taken at
    /// ImGui's pointer.
    void update(render::OrbitCamera& camera, const render::Viewport& view, const ButtonEvents& events = {});
    /// A left click in the view during the last update(): pressed and released there without
    /// dragging (ImGui coordinates), at the press's position. Empty otherwise.
    [[nodiscard]] std::optional<glm::dvec2> click() const { return click_; }

private:
    int dragButton_ = -1;  ///< 0 left (orbit), 1 right or 2 middle (pan); -1 none
    glm::dvec2 pressedAt_{0.0};
    std::optional<glm::dvec2> releasedAt_;  ///< where the held button came up, when its event said so
    bool dragged_ = false;  ///< the left button moved too far since the press to count as a click
    std::optional<glm::dvec2> click_;
};

} // namespace radiant::app
