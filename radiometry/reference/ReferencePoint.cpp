#include "radiometry/reference/ReferencePoint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/scene/View.h"

namespace radiant {
namespace {

std::string formatVector(const glm::dvec3& v) {
    std::ostringstream out;
    out.precision(6);
    out << v.x << "," << v.y << "," << v.z;
    return out.str();
}

/// How far x lies outside a convex planar face, in its plane (<= 0 inside).
double distanceOutside(const Face& face, const glm::dvec3& x) {
    double outside = std::numeric_limits<double>::lowest();
    const std::size_t count = face.vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& a = face.vertices[i];
        const glm::dvec3 inward = glm::cross(face.normal, face.vertices[(i + 1) % count] - a);
        const double length = glm::length(inward);
        if (length > 0) outside = std::max(outside, -glm::dot(x - a, inward) / length);
    }
    return outside;
}

double sceneDiagonal(const Scene& scene) {
    glm::dvec3 lo, hi;
    return sceneBounds(scene, lo, hi) ? std::max(glm::length(hi - lo), 1e-9) : 1.0;
}

} // namespace

ReferencePoint locateReferencePoint(const Scene& scene, const glm::dvec3& x, const glm::dvec3& n,
                                    const ReferencePointTolerance& tolerance) {
    const double length = glm::length(n);
    if (!(length > 0) || !std::isfinite(length) || !std::isfinite(glm::dot(x, x)))
        throw RadiantError({scene.name, std::isfinite(glm::dot(x, x)) ? "--normal" : "--point"},
                           "expected finite values and a non-zero normal, got point (" + formatVector(x) +
                               ") and normal (" + formatVector(n) + ")");
    const glm::dvec3 up = n / length;
    const double reach = tolerance.distance * sceneDiagonal(scene);

    bool found = false;
    ReferencePoint best;
    double bestAlignment = -2;
    std::string nearestName;
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        for (std::uint32_t f = 0; f < surface.faces.size(); ++f) {
            const Face& face = surface.faces[f];
            if (face.vertices.size() < 3 || !(face.area > 0)) continue;
            const double height = glm::dot(face.normal, x - face.vertices[0]);
            const double outside = std::max(0.0, distanceOutside(face, x));
            const double distance = std::hypot(height, outside);
            if (distance < nearestDistance) {
                nearestDistance = distance;
                nearestName = surface.name;
            }
            if (distance > reach) continue;
            const double alignment = glm::dot(face.normal, up);
            if (alignment > bestAlignment) {
                bestAlignment = alignment;
                best = ReferencePoint{s, f, x - height * face.normal, face.normal};
                found = true;
            }
        }
    }
    if (!found) {
        std::ostringstream message;
        message << "the point (" << formatVector(x) << ") lies on no surface";
        if (!nearestName.empty()) message << " (nearest: '" << nearestName << "', " << nearestDistance << " m away)";
        throw RadiantError({scene.name, "--point"}, message.str());
    }
    const double angle = std::acos(std::clamp(bestAlignment, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    if (angle > tolerance.angleDegrees) {
        std::ostringstream message;
        message.precision(3);
        message << "the normal (" << formatVector(n) << ") is " << angle << " degrees from the front of surface '"
                << scene.surfaces[best.surface].name << "' at (" << formatVector(x) << "), whose normal is ("
                << formatVector(best.normal) << "); the reference reads a surface facing its front";
        throw RadiantError({scene.name, "--normal"}, message.str());
    }
    return best;
}

} // namespace radiant
