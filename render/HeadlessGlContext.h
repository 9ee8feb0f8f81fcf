#pragma once
// An OpenGL context with no window and no display server: EGL on Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless), else an EGL device (EGL_EXT_platform_device). Draws only into
// framebuffer objects (there is no default framebuffer). For `radiant render` and `radiant bench`
// on a classroom server or in CI. 4.5 core, falling back to 3.3 core, as the window does.
// GL-free header.
#include <memory>
#include <string>

namespace radiant::render {

class HeadlessGlContext {
public:
    /// Makes the context current on the calling thread; null with `whyNot` set when EGL, the
    /// platforms above or a 3.3+ core context are unavailable.
    static std::unique_ptr<HeadlessGlContext> tryCreate(std::string& whyNot);
    ~HeadlessGlContext();
    HeadlessGlContext(const HeadlessGlContext&) = delete;
    HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

    /// "surfaceless" or "device": which EGL platform gave the display.
    [[nodiscard]] const std::string& platform() const { return platform_; }

private:
    HeadlessGlContext() = default;
    void* display_ = nullptr;  // EGLDisplay (initialised, never terminated), opaque to keep EGL out of this header
    void* context_ = nullptr;  // EGLContext
    std::string platform_;
};

} // namespace radiant::render
