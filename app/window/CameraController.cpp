#include "app/window/CameraController.h"

#include <imgui.h>
#include <numbers>

#include <glm/geometric.hpp>

namespace radiant::app {

void CameraController::update(render::OrbitCamera& camera, const render::Viewport& view) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool overView = io.MousePos.x >= static_cast<float>(view.x) &&
                          io.MousePos.x < static_cast<float>(view.x + view.width) &&
                          io.MousePos.y >= static_cast<float>(view.y) &&
                          io.MousePos.y < static_cast<float>(view.y + view.height);
    click_.reset();
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
    if (dragButton_ >= 0 && !io.MouseDown[dragButton_]) {
        if (dragButton_ == 0 && !dragged_) click_ = pressedAt_;
        dragButton_ = -1;
    }
    bool pressedNow = false;
    if (dragButton_ < 0 && overView && !io.WantCaptureMouse)
        for (int button = 0; button < 3; ++button)
            if (io.MouseClicked[button]) {
                dragButton_ = button;
                pressedAt_ = mouse;
                dragged_ = false;
                pressedNow = true;
            }
    // A hand on a projector clicker wobbles a few pixels; more than that is an orbit, not a pick.
    constexpr double kClickSlop = 4.0;
    if (dragButton_ == 0 && glm::length(mouse - pressedAt_) > kClickSlop) dragged_ = true;

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
