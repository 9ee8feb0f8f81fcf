#include "render/GlContext.h"

#include <epoxy/gl.h>

#include "render/gl/Framebuffer.h"

namespace radiant::render {
namespace {
std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? std::string(reinterpret_cast<const char*>(text)) : std::string("(unknown)");
}
} // namespace

GlInfo queryGlInfo() {
    GlInfo info{glString(GL_RENDERER), glString(GL_VERSION), glString(GL_VENDOR), 0, 0};
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    return info;
}

void beginWindowFrame(int framebufferWidth, int framebufferHeight, const Viewport& sceneViewport,
                      const glm::vec3& background) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glClearColor(background.x, background.y, background.z, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // GL counts rows from the bottom.
    glViewport(sceneViewport.x, framebufferHeight - sceneViewport.y - sceneViewport.height, sceneViewport.width,
               sceneViewport.height);
}

void useViewport(int framebufferHeight, const Viewport& viewport) {
    glViewport(viewport.x, framebufferHeight - viewport.y - viewport.height, viewport.width, viewport.height);
}

void useWholeWindow(int framebufferWidth, int framebufferHeight) {
    glViewport(0, 0, framebufferWidth, framebufferHeight);
}

ImageRgb8 readWindowPixels(int framebufferWidth, int framebufferHeight) {
    return gl::readPixelsRgb8(0, 0, 0, framebufferWidth, framebufferHeight);
}

} // namespace radiant::render
