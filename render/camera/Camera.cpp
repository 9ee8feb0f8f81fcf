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

Camera cameraFromView(const View& view) {
    Camera camera;
    camera.eye = view.eye;
    camera.forward = glm::normalize(view.target - view.eye);
    camera.up = view.up;
    camera.fieldOfView = Radians(view.verticalFov);
    const double distance = glm::length(view.target - view.eye);
    camera.nearPlane = std::max(distance * 1e-3, 1e-4);
    camera.farPlane = std::max(distance * 100.0, camera.nearPlane * 10.0);
    return camera;
}

View viewFromCamera(const Camera& camera, double aspect) {
    return {camera.eye, camera.eye + camera.forward, camera.up, camera.verticalFieldOfView(aspect).value(), aspect};
}

Camera cornellCamera() { return cameraFromView(cornellView()); }

Camera framingCamera(const glm::dvec3& lo, const glm::dvec3& hi) { return cameraFromView(framingView(lo, hi)); }

glm::dvec3 projectToPixel(const Camera& camera, const Viewport& viewport, const glm::dvec3& world) {
    const glm::dvec4 clip = camera.viewProjection(viewport.aspect()) * glm::dvec4(world, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {viewport.x + (ndc.x + 1.0) / 2.0 * viewport.width,
            viewport.y + (1.0 - ndc.y) / 2.0 * viewport.height,
            (ndc.z + 1.0) / 2.0};
}

} // namespace radiant::render
