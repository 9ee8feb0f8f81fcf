#include "render/OffscreenRender.h"

#include "render/gl/Framebuffer.h"

namespace radiant::render {

ImageRgb8 renderOffscreen(const SceneRenderer& renderer, const Camera& camera, int width, int height,
                          const glm::vec3& background) {
    gl::Framebuffer target(width, height);
    target.bindForDrawing();
    glDisable(GL_SCISSOR_TEST);
    glClearColor(background.x, background.y, background.z, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.draw(camera, static_cast<double>(width) / static_cast<double>(height));
    ImageRgb8 image = target.readRgb8();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

} // namespace radiant::render
