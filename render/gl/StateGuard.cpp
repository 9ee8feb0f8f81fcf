#include "render/gl/StateGuard.h"

namespace radiant::render::gl {
namespace {
void setEnabled(GLenum capability, GLboolean on) { on ? glEnable(capability) : glDisable(capability); }
} // namespace

StateGuard::StateGuard()
    : blend_(glIsEnabled(GL_BLEND)),
      cull_(glIsEnabled(GL_CULL_FACE)),
      depthTest_(glIsEnabled(GL_DEPTH_TEST)),
      scissor_(glIsEnabled(GL_SCISSOR_TEST)) {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthWrite_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetIntegerv(GL_CULL_FACE_MODE, &cullMode_);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendSourceRgb_);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendDestinationRgb_);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSourceAlpha_);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDestinationAlpha_);
}

StateGuard::~StateGuard() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    setEnabled(GL_BLEND, blend_);
    setEnabled(GL_CULL_FACE, cull_);
    setEnabled(GL_DEPTH_TEST, depthTest_);
    setEnabled(GL_SCISSOR_TEST, scissor_);
    glDepthMask(depthWrite_);
    glDepthFunc(static_cast<GLenum>(depthFunc_));
    glCullFace(static_cast<GLenum>(cullMode_));
    glBlendFuncSeparate(static_cast<GLenum>(blendSourceRgb_), static_cast<GLenum>(blendDestinationRgb_),
                        static_cast<GLenum>(blendSourceAlpha_), static_cast<GLenum>(blendDestinationAlpha_));
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace radiant::render::gl
