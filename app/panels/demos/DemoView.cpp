#include "app/panels/demos/DemoView.h"

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

void DemoView::open(const LectureDemo& demo) {
    if (!sceneCamera_) sceneCamera_.emplace(orbit_);
    const DemoFraming framing = demo.framing();
    orbit_ = render::OrbitCamera(framing.camera, framing.pivot);
    active_ = &demo;
}

void DemoView::close() {
    if (!active_) return;
    orbit_ = *sceneCamera_;
    sceneCamera_.reset();
    active_ = nullptr;
}

} // namespace radiant::app
