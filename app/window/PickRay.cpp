#include "app/window/PickRay.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace radiant::app {

PickRay pickRay(const render::Camera& camera, const render::Viewport& viewport, const glm::dvec2& pixel) {
    // Pixel -> normalised device coordinates (y up), then through the inverse view-projection at the
    // near and far planes; the two points fix the ray without assuming a pinhole convention here.
    const double ndcX = 2.0 * (pixel.x - viewport.x) / viewport.width - 1.0;
    const double ndcY = 1.0 - 2.0 * (pixel.y - viewport.y) / viewport.height;
    const glm::dmat4 inverse = glm::inverse(camera.viewProjection(viewport.aspect()));
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    return {a, glm::normalize(b - a)};
}

} // namespace radiant::app
