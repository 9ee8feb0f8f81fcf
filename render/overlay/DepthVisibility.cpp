#include "render/overlay/DepthVisibility.h"

#include <epoxy/gl.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace radiant::render {

bool inFrontOfDepth(const Camera& camera, const Viewport& viewport, const glm::dvec3& world, double bufferDepth) {
    const glm::dvec3 pixel = projectToPixel(camera, viewport, world);
    // The surface the buffer holds at that pixel, back in world space.
    const glm::dvec4 ndc{(pixel.x - viewport.x) / viewport.width * 2.0 - 1.0,
                         1.0 - (pixel.y - viewport.y) / viewport.height * 2.0, bufferDepth * 2.0 - 1.0, 1.0};
    const glm::dvec4 surface = glm::inverse(camera.viewProjection(viewport.aspect())) * ndc;
    const double surfaceDistance = glm::dot(glm::dvec3(surface) / surface.w - camera.eye, camera.forward);
    const double pointDistance = glm::dot(world - camera.eye, camera.forward);
    return pointDistance <= surfaceDistance + 0.01 * pointDistance;
}

bool visibleInDepthBuffer(const Camera& camera, const Viewport& viewport, int framebufferHeight, const glm::dvec3& world) {
    const glm::dvec3 pixel = projectToPixel(camera, viewport, world);
    if (!(pixel.z > 0 && pixel.z < 1)) return false;
    const double column = std::floor(pixel.x), row = std::floor(pixel.y);
    if (column < viewport.x || column >= viewport.x + viewport.width || row < viewport.y ||
        row >= viewport.y + viewport.height)
        return false;
    float depth = 1.0f;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // GL counts rows from the bottom.
    glReadPixels(static_cast<GLint>(column), framebufferHeight - 1 - static_cast<GLint>(row), 1, 1, GL_DEPTH_COMPONENT,
                 GL_FLOAT, &depth);
    return inFrontOfDepth(camera, viewport, world, static_cast<double>(depth));
}

} // namespace radiant::render
