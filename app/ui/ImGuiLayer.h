#pragma once
// Dear ImGui on a GLFW window: context, platform and GL backends, the lab's theme and its fonts.
// The UI scale rebuilds the font atlas at the new pixel size (sharp text on a projector) and
// rescales the style's spacing from the unscaled theme.
#include <optional>
#include <vector>

struct GLFWwindow;

namespace radiant::app {

class ImGuiLayer {
public:
    /// Call after the window's callbacks are installed: ImGui chains to them.
    ImGuiLayer(GLFWwindow* window, float uiScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    /// The pointer as tests drive it (ImGui window coordinates), instead of the real one; nullopt
    /// gives the real pointer back.
    struct MouseOverride {
        float x = 0, y = 0;
        bool leftDown = false;
    };
    void overrideMouse(std::optional<MouseOverride> mouse);

    /// True while the UI owns the keyboard: a text field is being edited or a widget is held (a
    /// slider dragged). Everywhere else the lab's shortcuts act, whatever was clicked last.
    [[nodiscard]] static bool keyboardClaimed();

    /// Every key press the window gets, before ImGui's own callback sees it. Dear ImGui 1.86 (Debian
    /// 12's) reads keys as held-down states once per frame, so a press and release that arrive
    /// between two frames (xdotool, a presenter remote, a quick tap on a slow software-GL frame)
    /// were never seen: Return in a path field did nothing. newFrame() holds such a key down for
    /// one frame and lets it go on the next, as ImGui 1.87's input queue does.
    void notePress(int glfwKey);

    void newFrame();
    void render();

    [[nodiscard]] float uiScale() const { return scale_; }
    /// Takes effect at the next newFrame() (the atlas cannot change mid-frame).
    void setUiScale(float scale);

private:
    void applyScale();

    float scale_;
    float appliedScale_ = 0;
    std::optional<MouseOverride> mouseOverride_;
    std::vector<int> pressedSinceFrame_;  ///< GLFW key codes pressed since the last newFrame()
    std::vector<int> heldForOneFrame_;    ///< keys newFrame() showed down that were already up
};

} // namespace radiant::app
