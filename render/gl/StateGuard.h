#pragma once
// Saves the GL state a drawing pass off the main scene changes (the hemicube's item buffer, the
// dome overlay) and restores it when the pass's scope ends, so the caller's next draw finds its
// framebuffer, viewport, tests, blend function and depth settings as it left them.
#include <epoxy/gl.h>

namespace radiant::render::gl {

class StateGuard {
public:
    StateGuard();
    /// Also leaves no program and no vertex array bound: a program saved by name may have been
    /// deleted while current, and binding its name again would be an error or another program.
    ~StateGuard();
    // A guard belongs to one scope; a moved-from one would restore twice or need a flag.
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;
    StateGuard(StateGuard&&) = delete;
    StateGuard& operator=(StateGuard&&) = delete;

private:
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
    GLint viewport_[4]{};
    GLboolean blend_ = GL_FALSE, cull_ = GL_FALSE, depthTest_ = GL_FALSE, scissor_ = GL_FALSE;
    GLboolean depthWrite_ = GL_TRUE;
    GLint depthFunc_ = GL_LESS, cullMode_ = GL_BACK;
    GLint blendSourceRgb_ = GL_ONE, blendDestinationRgb_ = GL_ZERO, blendSourceAlpha_ = GL_ONE,
          blendDestinationAlpha_ = GL_ZERO;
};

} // namespace radiant::render::gl
