#pragma once
// Where the mouse buttons went down and up, recorded from GLFW's events in the order they arrive
// (issue #16). ImGui 1.86's GLFW backend reads the pointer once per frame (glfwGetCursorPos, on X11
// the server's pointer now), so on a slow frame a click that the hand followed with a move landed
// where the pointer had got to by then: the probe took the wrong point, or a click became a drag.
// GLFW reports motion and buttons in event order, so the position last reported before a press is
// where the press happened. GL-free: the window's callbacks feed it, CameraController reads it.
#include <array>
#include <optional>

#include <glm/vec2.hpp>

namespace radiant::app {

/// One button's events since the last frame, in window coordinates (ImGui's units).
struct ButtonEvent {
    std::optional<glm::dvec2> pressedAt;   ///< the last press's position
    std::optional<glm::dvec2> releasedAt;  ///< the position of the release after it (or after an earlier press)
};

/// Left, right, middle (ImGui's and GLFW's order).
inline constexpr int kRecordedButtons = 3;
using ButtonEvents = std::array<ButtonEvent, kRecordedButtons>;

class ButtonRecorder {
public:
    /// From the cursor-position callback (and once from glfwGetCursorPos if a press comes first).
    void moved(const glm::dvec2& windowPoint) { pointer_ = windowPoint; }
    [[nodiscard]] bool knowsPointer() const { return pointer_.has_value(); }
    /// From the mouse-button callback; buttons past the middle one are not recorded.
    void button(int button, bool pressed) {
        if (button < 0 || button >= kRecordedButtons || !pointer_) return;
        ButtonEvent& event = events_[static_cast<std::size_t>(button)];
        if (pressed) {
            event.pressedAt = pointer_;
            event.releasedAt.reset();
        } else {
            event.releasedAt = pointer_;
        }
    }
    /// The events since the previous take(), forgotten here: a frame takes them once.
    [[nodiscard]] ButtonEvents take() {
        const ButtonEvents taken = events_;
        events_ = {};
        return taken;
    }

private:
    std::optional<glm::dvec2> pointer_;
    ButtonEvents events_{};
};

} // namespace radiant::app
