#include "app/window/CameraController.h"

#include <imgui.h>
#include <numbers>

#include <glm/geometric.hpp>

namespace radiant::app {

void CameraController::update(render::OrbitCamera& camera, const render::Viewport& view, const ButtonEvents& events) {
    const ImGuiIO& io = ImGui::GetIO();
    const auto inView = [&](const glm::dvec2& p) {
        return p.x >= view.x && p.x < view.x + view.width && p.y >= view.y && p.y < view.y + view.height;
    };
    click_.reset();
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
    const bool overView = inView(mouse);
    if (dragButton_ >= 0 && events[static_cast<std::size_t>(dragButton_)].releasedAt)
        releasedAt_ = events[static_cast<std::size_t>(dragButton_)].releasedAt;
    // A hand on a projector clicker wobbles a few pixels; more than that is an orbit, not a pick.
    // Measured to where the button came up when its event said so: a slow frame sees the pointer
    // wherever the hand took it after the click.
    constexpr double kClickSlop = 4.0;
    const auto movedTooFar = [&] { return glm::length(releasedAt_.value_or(mouse) - pressedAt_) > kClickSlop; };
    if (dragButton_ >= 0 && !io.MouseDown[dragButton_]) {
        if (dragButton_ == 0 && !dragged_ && !movedTooFar()) click_ = pressedAt_;
        dragButton_ = -1;
    }
    bool pressedNow = false;
    if (dragButton_ < 0 && !io.WantCaptureMouse)
        for (int button = 0; button < kRecordedButtons; ++button) {
            const ButtonEvent& event = events[static_cast<std::size_t>(button)];
            const glm::dvec2 at = event.pressedAt.value_or(mouse);
            if (io.MouseClicked[button] && inView(at)) {
                dragButton_ = button;
                pressedAt_ = at;
                releasedAt_ = event.releasedAt;
                dragged_ = false;
                pressedNow = true;
            }
        }
    if (dragButton_ == 0 && movedTooFar()) dragged_ = true;

    // The press frame's delta is how the pointer got to where it was pressed (a jump, when an idle
    // lab drew no frame in between, or a touch screen's tap): not part of the drag.
    if (dragButton_ >= 0 && !pressedNow) {
        const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
        const double height = static_cast<double>(view.height);
        if (dragButton_ == 0) {
            // Dragging across the view's full height turns the box half a turn: the object follows the hand.
            const double radiansPerPixel = std::numbers::pi / height;
            camera.orbit(Radians(-dx * radiansPerPixel), Radians(-dy * radiansPerPixel));
        } else {
            camera.pan(dx / height, -dy / height);
        }
    }
    if (overView && !io.WantCaptureMouse && io.MouseWheel != 0.0f) camera.zoom(static_cast<double>(io.MouseWheel));
}

} // namespace radiant::app
