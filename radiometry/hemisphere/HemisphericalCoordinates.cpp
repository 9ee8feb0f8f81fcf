#include "radiometry/hemisphere/HemisphericalCoordinates.h"

#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant {

HemisphereFrame::HemisphereFrame(const glm::dvec3& normal) {
    const double length = glm::length(normal);
    if (!(length > 0) || !std::isfinite(length))
        throw RadiantError({"", "hemisphere frame"}, "normal (" + std::to_string(normal.x) + ", " +
                                                         std::to_string(normal.y) + ", " + std::to_string(normal.z) +
                                                         ") has no direction");
    normal_ = normal / length;
    // Duff et al. 2017, listing 3: branch-free apart from the sign, no normalisation needed.
    const double sign = std::copysign(1.0, normal_.z);
    const double a = -1.0 / (sign + normal_.z);
    const double b = normal_.x * normal_.y * a;
    tangent_ = {1.0 + sign * normal_.x * normal_.x * a, sign * b, -sign * normal_.x};
    bitangent_ = {b, sign + normal_.y * normal_.y * a, -normal_.y};
}

glm::dvec3 HemisphereFrame::toWorld(const glm::dvec3& local) const {
    return local.x * tangent_ + local.y * bitangent_ + local.z * normal_;
}

glm::dvec3 HemisphereFrame::toLocal(const glm::dvec3& world) const {
    return {glm::dot(world, tangent_), glm::dot(world, bitangent_), glm::dot(world, normal_)};
}

HemisphereFrame HemisphereFrame::turned(Radians angle) const {
    const double c = std::cos(angle.value()), s = std::sin(angle.value());
    HemisphereFrame frame = *this;
    frame.tangent_ = c * tangent_ + s * bitangent_;
    frame.bitangent_ = -s * tangent_ + c * bitangent_;
    return frame;
}

glm::dvec3 localDirection(SphericalDirection angles) {
    const double sinTheta = std::sin(angles.theta.value());
    return {sinTheta * std::cos(angles.phi.value()), sinTheta * std::sin(angles.phi.value()),
            std::cos(angles.theta.value())};
}

glm::dvec3 directionFromAngles(const HemisphereFrame& frame, SphericalDirection angles) {
    return frame.toWorld(localDirection(angles));
}

SphericalDirection anglesFromDirection(const HemisphereFrame& frame, const glm::dvec3& direction) {
    const glm::dvec3 local = frame.toLocal(direction);
    const double length = glm::length(local);
    if (!(length > 0))
        throw RadiantError({"", "hemisphere direction"}, "the zero vector has no direction");
    // atan2 of (sin, cos) keeps theta accurate near the pole, where acos loses digits.
    const double sinTheta = std::hypot(local.x, local.y);
    const double theta = std::atan2(sinTheta, local.z);
    double phi = std::atan2(local.y, local.x);
    if (phi < 0) phi += 2.0 * std::numbers::pi;
    return {Radians(theta), Radians(phi)};
}

SolidAngle differentialSolidAngle(Radians theta, Radians dTheta, Radians dPhi) {
    return SolidAngle(std::sin(theta.value()) * dTheta.value() * dPhi.value());
}

} // namespace radiant
