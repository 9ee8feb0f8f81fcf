#include "render/camera/OrbitCamera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace radiant::render {
namespace {
constexpr double kMaxPitch = 89.0 * std::numbers::pi / 180.0;
}

OrbitCamera::OrbitCamera(const Camera& home, const glm::dvec3& centre) : home_(home) {
    const glm::dvec3 f = glm::normalize(home.forward);
    homeDistance_ = std::max(glm::dot(centre - home.eye, f), 1e-3);
    homePivot_ = home.eye + f * homeDistance_;
    homeYaw_ = std::atan2(f.x, f.z);
    homePitch_ = std::asin(std::clamp(f.y, -1.0, 1.0));
    reset();
}

void OrbitCamera::reset() {
    pivot_ = homePivot_;
    distance_ = homeDistance_;
    yaw_ = homeYaw_;
    pitch_ = homePitch_;
}

glm::dvec3 OrbitCamera::forward() const {
    return {std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), std::cos(yaw_) * std::cos(pitch_)};
}

Camera OrbitCamera::camera() const {
    Camera c = home_;
    c.forward = forward();
    c.eye = pivot_ - c.forward * distance_;
    c.up = {0, 1, 0};
    return c;
}

void OrbitCamera::orbit(Radians yaw, Radians pitch) {
    yaw_ += yaw.value();
    pitch_ = std::clamp(pitch_ + pitch.value(), -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double rightFraction, double upFraction) {
    const glm::dvec3 f = forward();
    const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, f);
    // The visible height at the pivot's depth is 2 d tan(fov/2).
    const double visibleHeight = 2.0 * distance_ * std::tan(home_.fieldOfView.value() / 2.0);
    pivot_ -= (right * rightFraction + up * upFraction) * visibleHeight;
}

void OrbitCamera::zoom(double steps) {
    distance_ = std::clamp(distance_ * std::pow(0.85, steps), 0.05, 1000.0);
}

} // namespace radiant::render
