#include "radiometry/solidangle/PolygonSolidAngle.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant {

SolidAngle signedTriangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double tripleProduct = glm::dot(a, glm::cross(b, c));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    // a . (b x c) > 0 when the corners run counter-clockwise seen from outside the origin's side, i.e.
    // the origin is behind the triangle; the sign flip makes "seen from the front" positive.
    return SolidAngle(-2.0 * std::atan2(tripleProduct, denominator));
}

SolidAngle signedPolygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon) {
    if (polygon.size() < 3)
        throw RadiantError({"", "polygon solid angle"},
                           "a polygon needs at least 3 vertices, got " + std::to_string(polygon.size()));
    // Newell's normal: its length is twice the area, so the plane test below is scale-free.
    glm::dvec3 newell(0.0);
    double extent = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& p = polygon[i];
        const glm::dvec3& q = polygon[(i + 1) % polygon.size()];
        newell += glm::cross(p, q);
        extent = std::max(extent, glm::length(p - x));
    }
    const double twiceArea = glm::length(newell);
    if (!(twiceArea > 0)) return SolidAngle(0.0);
    const double height = glm::dot(newell / twiceArea, polygon[0] - x);
    // In the plane (to rounding) the polygon is seen edge-on; atan2 would otherwise return +-2 pi
    // depending on the sign of a rounding error.
    if (std::abs(height) <= 1e-12 * extent) return SolidAngle(0.0);

    const glm::dvec3 a = polygon[0] - x;
    SolidAngle sum(0.0);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        sum += signedTriangleSolidAngle(a, polygon[i] - x, polygon[i + 1] - x);
    return sum;
}

SolidAngle polygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon) {
    return SolidAngle(std::abs(signedPolygonSolidAngle(x, polygon).value()));
}

SolidAngle solidAngleAboveHorizon(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon) {
    const double length = glm::length(n);
    if (!(length > 0))
        throw RadiantError({"", "solid angle above the horizon"}, "the normal must be non-zero");
    const glm::dvec3 up = n / length;
    std::vector<glm::dvec3> clipped;
    clipped.reserve(polygon.size() + 1);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& start = polygon[(i + polygon.size() - 1) % polygon.size()];
        const glm::dvec3& end = polygon[i];
        const double hStart = glm::dot(up, start - x);
        const double hEnd = glm::dot(up, end - x);
        if ((hStart >= 0) != (hEnd >= 0)) {
            glm::dvec3 crossing = start + (end - start) * (hStart / (hStart - hEnd));
            crossing -= up * glm::dot(up, crossing - x);  // exactly on the horizon
            clipped.push_back(crossing);
        }
        if (hEnd >= 0) clipped.push_back(end);
    }
    if (clipped.size() < 3) return SolidAngle(0.0);
    return polygonSolidAngle(x, clipped);
}

} // namespace radiant
