#pragma once
// A current GL context for drawing into framebuffer objects only (`radiant render`, `radiant bench`):
// headless EGL when the system has it, so neither needs an X server; else a hidden GLFW window.
// EGL comes first even with a display, so a picture does not depend on whether DISPLAY is set.
// GL-free header.
#include <memory>
#include <string>

namespace radiant::render {
class HeadlessGlContext;
}

namespace radiant::app {

class Window;

class OffscreenContext {
public:
    /// Throws RadiantError naming why each way failed when neither gives a 3.3+ core context.
    explicit OffscreenContext(const std::string& purpose);
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    /// "EGL (surfaceless)", "EGL (device)" or "GLFW hidden window".
    [[nodiscard]] const std::string& kind() const { return kind_; }

private:
    std::unique_ptr<render::HeadlessGlContext> headless_;
    std::unique_ptr<Window> window_;
    std::string kind_;
};

} // namespace radiant::app
