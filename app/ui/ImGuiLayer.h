#pragma once
// Dear ImGui on a GLFW window: context, platform and GL backends, the lab's theme and its fonts.
// The UI scale rebuilds the font atlas at the new pixel size (sharp text on a projector) and
// rescales the style's spacing from the unscaled theme.
struct GLFWwindow;

namespace radiant::app {

class ImGuiLayer {
public:
    /// Call after the window's callbacks are installed: ImGui chains to them.
    ImGuiLayer(GLFWwindow* window, float uiScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void newFrame();
    void render();

    [[nodiscard]] float uiScale() const { return scale_; }
    /// Takes effect at the next newFrame() (the atlas cannot change mid-frame).
    void setUiScale(float scale);

private:
    void applyScale();

    float scale_;
    float appliedScale_ = 0;
};

} // namespace radiant::app
