#include "app/window/OffscreenContext.h"

#include "app/window/Window.h"
#include "radiometry/common/Error.h"
#include "render/HeadlessGlContext.h"

namespace radiant::app {

OffscreenContext::OffscreenContext(const std::string& purpose) {
    std::string eglWhyNot;
    headless_ = render::HeadlessGlContext::tryCreate(eglWhyNot);
    if (headless_) {
        kind_ = "EGL (" + headless_->platform() + ")";
        return;
    }
    try {
        // Any size will do: the pictures go to framebuffers of their own size.
        window_ = std::make_unique<Window>(WindowOptions{64, 64, purpose, /*visible=*/false, /*vsync=*/false});
        kind_ = "GLFW hidden window";
    } catch (const RadiantError& e) {
        throw RadiantError({"OpenGL", ""}, "no headless EGL context (" + eglWhyNot + ") and no window either (" +
                                               e.detail() + ")");
    }
}

OffscreenContext::~OffscreenContext() = default;

} // namespace radiant::app
