#include "render/camera/Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace radiant::render {

glm::dmat4 Camera::view() const { return glm::lookAt(eye, eye + forward, up); }

Radians Camera::verticalFieldOfView(double aspect) const {
    if (aspect >= 1.0) return fieldOfView;
    return Radians(2.0 * std::atan(std::tan(fieldOfView.value() / 2.0) / aspect));
}

glm::dmat4 Camera::projection(double aspect) const {
    return glm::perspective(verticalFieldOfView(aspect).value(), aspect, nearPlane, farPlane);
}

Camera cornellCamera() {
    Camera camera;
    camera.eye = {0.278, 0.273, -0.8};
    camera.forward = {0, 0, 1};
    camera.up = {0, 1, 0};
    constexpr double focalLengthMm = 35.0, filmHeightMm = 25.0;
    camera.fieldOfView = Radians(2.0 * std::atan(filmHeightMm / 2.0 / focalLengthMm));
    return camera;
}

Camera framingCamera(const glm::dvec3& lo, const glm::dvec3& hi) {
    Camera camera = cornellCamera();
    // A three-quarter view from above: a head-on view of a box shows one flat square.
    camera.forward = glm::normalize(glm::dvec3(-0.55, -0.45, 1.0));
    const glm::dvec3 centre = (lo + hi) / 2.0;
    const double radius = std::max(glm::length(hi - lo) / 2.0, 1e-3);
    const double distance = radius / std::sin(camera.fieldOfView.value() / 2.0);
    camera.eye = centre - camera.forward * distance;
    camera.nearPlane = std::max(distance * 1e-3, 1e-4);
    camera.farPlane = distance + radius * 4.0;
    return camera;
}

glm::dvec3 projectToPixel(const Camera& camera, const Viewport& viewport, const glm::dvec3& world) {
    const glm::dvec4 clip = camera.viewProjection(viewport.aspect()) * glm::dvec4(world, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {viewport.x + (ndc.x + 1.0) / 2.0 * viewport.width,
            viewport.y + (1.0 - ndc.y) / 2.0 * viewport.height,
            (ndc.z + 1.0) / 2.0};
}

} // namespace radiant::render
