#pragma once
// The GLFW window and its OpenGL context: 4.5 core, falling back to 3.3 core (said on stderr and in
// the Info panel). Owns GLFW's initialisation for its lifetime. GL-free header.
#include <string>

struct GLFWwindow;

namespace radiant::app {

struct WindowOptions {
    int width = 1600;
    int height = 1000;
    std::string title = "Radiant";
    bool visible = true;
    bool vsync = true;
    /// Multisample anti-aliasing samples; 0 = off, the default: on llvmpipe (software GL, what Xvfb
    /// and CI give) 4x MSAA multiplies the fragment cost and frames took 70-270 ms, and the patch
    /// shader already draws its edges anti-aliased (fwidth), so MSAA buys little for what it costs.
    int msaaSamples = 0;
};

class Window {
public:
    /// Throws RadiantError when GLFW cannot start (no display) or no 3.3+ core context exists.
    explicit Window(const WindowOptions& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    [[nodiscard]] GLFWwindow* handle() const { return window_; }
    [[nodiscard]] bool shouldClose() const;
    void requestClose();
    void swapBuffers();
    void setTitle(const std::string& title);

    /// Size of the drawable in pixels (may differ from window coordinates on high-DPI displays).
    void framebufferSize(int& width, int& height) const;
    /// Framebuffer pixels per window coordinate unit.
    [[nodiscard]] float pixelRatio() const;

    /// Empty when the requested 4.5 context was created; otherwise why the fallback was taken.
    [[nodiscard]] const std::string& fallbackNote() const { return fallbackNote_; }
    [[nodiscard]] bool multisampled() const { return multisampled_; }

private:
    GLFWwindow* window_ = nullptr;
    std::string fallbackNote_;
    bool multisampled_ = false;
};

} // namespace radiant::app
