#include "app/panels/demos/DemoView.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "app/panels/demos/LectureDemo.h"

namespace radiant::app {

DemoFraming framingFrom(const glm::dvec3& eye, const glm::dvec3& target, double fieldOfViewDegrees) {
    DemoFraming framing;
    const double distance = glm::length(target - eye);
    framing.camera.eye = eye;
    framing.camera.forward = (target - eye) / distance;
    framing.camera.fieldOfView = Radians(fieldOfViewDegrees * std::numbers::pi / 180.0);
    framing.camera.nearPlane = distance / 200.0;
    framing.camera.farPlane = distance * 20.0;
    framing.pivot = target;
    return framing;
}

render::Camera showingFramedWidth(render::Camera camera, double aspect, double framedAspect) {
    if (aspect >= framedAspect || aspect <= 0) return camera;
    // Landscape: the vertical field grows until the width is the framed one. Portrait: the camera
    // takes its field as the horizontal one (render::Camera), which grows to the framed width too.
    const double widen = framedAspect / std::max(aspect, 1.0);
    camera.fieldOfView = Radians(2 * std::atan(std::tan(0.5 * camera.fieldOfView.value()) * widen));
    return camera;
}

void DemoView::open(const LectureDemo& demo) {
    if (!sceneCamera_) sceneCamera_.emplace(orbit_);
    const DemoFraming framing = demo.framing();
    orbit_ = render::OrbitCamera(framing.camera, framing.pivot);
    active_ = &demo;
    framedAspect_ = framing.framedAspect;
}

void DemoView::close() {
    if (!active_) return;
    orbit_ = *sceneCamera_;
    sceneCamera_.reset();
    active_ = nullptr;
    framedAspect_ = 0;
}

render::Camera DemoView::shownCamera(const render::Camera& orbitCamera, double aspect) const {
    return active_ ? showingFramedWidth(orbitCamera, aspect, framedAspect_) : orbitCamera;
}

} // namespace radiant::app
