#include "render/camera/HomeCamera.h"

#include <glm/common.hpp>
#include <limits>

namespace radiant::render {

void sceneBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    for (const Surface& surface : scene.surfaces)
        for (const Face& face : surface.faces)
            for (const glm::dvec3& v : face.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
}

Camera homeCamera(const Scene& scene) {
    if (scene.name == "cornell-box") return cornellCamera();
    glm::dvec3 lo, hi;
    sceneBounds(scene, lo, hi);
    return framingCamera(lo, hi);
}

} // namespace radiant::render
