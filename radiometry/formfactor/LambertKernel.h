#pragma once
// Lambert's contour integral for the form factor from a differential area to a polygon, shared by
// the public point-to-polygon function and the area quadrature (which calls it in its inner loop,
// so everything here is inline and allocation-free).
//
// J. H. Lambert, Photometria (1760); in the form used for radiosity by Baum, Rushmeier & Winget,
// "Improving radiosity solutions through the use of analytically determined form-factors",
// SIGGRAPH 1989:  F = 1/(2 pi) sum_i gamma_i n . (R_i x R_i+1) / |R_i x R_i+1|.
//
// The part of the polygon below the tangent plane of x is clipped away first (Sutherland-Hodgman,
// streamed: clipped vertices go straight into the sum, so no clipped polygon is ever stored). The
// sum's sign tells the orientation of the polygon as seen from x: a polygon whose front faces x
// (counter-clockwise seen from x) gives a negative sum, one seen from its back a positive sum, which
// is clamped to zero because surfaces emit from their front only.
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace radiant::detail {

/// gamma * n . unit(a x b), gamma the angle between a and b: one edge of Lambert's sum. atan2 of
/// |cross| and dot keeps gamma accurate for tiny and for nearly straight angles, where acos fails.
inline double lambertEdgeTerm(const glm::dvec3& n, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 c = glm::cross(a, b);
    const double sine = std::sqrt(glm::dot(c, c));
    // x on the edge's line: the edge subtends no angle (or x lies on the edge, a null set).
    if (!(sine > 0)) return 0.0;
    return std::atan2(sine, glm::dot(a, b)) * glm::dot(n, c) / sine;
}

/// Lambert's signed sum over the polygon vertices[0..count) (any size, any container indexable by
/// std::size_t), clipped to the half-space n . (p - x) >= 0. Negative when the front faces x.
template <class Vertices>
double clippedLambertSum(const glm::dvec3& x, const glm::dvec3& n, const Vertices& vertices, std::size_t count) {
    if (count < 3) return 0.0;
    // Fast path, the common case: the whole polygon lies above the tangent plane.
    bool allAbove = true;
    bool allBelow = true;
    for (std::size_t i = 0; i < count; ++i) {
        const double h = glm::dot(n, vertices[i] - x);
        allAbove = allAbove && h >= 0;
        allBelow = allBelow && h <= 0;
    }
    if (allBelow) return 0.0;
    double sum = 0.0;
    if (allAbove) {
        glm::dvec3 previous = vertices[count - 1] - x;
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3 current = vertices[i] - x;
            sum += lambertEdgeTerm(n, previous, current);
            previous = current;
        }
        return sum;
    }
    // Sutherland-Hodgman against the tangent plane, each output vertex fed to the running sum.
    glm::dvec3 first{0.0};
    glm::dvec3 last{0.0};
    bool started = false;
    const auto emit = [&](const glm::dvec3& r) {
        if (started) {
            sum += lambertEdgeTerm(n, last, r);
        } else {
            first = r;
            started = true;
        }
        last = r;
    };
    glm::dvec3 start = vertices[count - 1] - x;
    double startHeight = glm::dot(n, start);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 end = vertices[i] - x;
        const double endHeight = glm::dot(n, end);
        const bool startInside = startHeight >= 0;
        const bool endInside = endHeight >= 0;
        if (startInside != endInside) {
            const double t = startHeight / (startHeight - endHeight);
            glm::dvec3 crossing = start + (end - start) * t;
            // Put it exactly on the plane: it bounds the visible part, and rounding must not push
            // it below.
            crossing -= n * glm::dot(n, crossing);
            emit(crossing);
        }
        if (endInside) emit(end);
        start = end;
        startHeight = endHeight;
    }
    if (started) sum += lambertEdgeTerm(n, last, first);
    return sum;
}

/// The form factor from the clamped sum: front faces only.
inline double formFactorFromLambertSum(double sum) {
    return sum < 0 ? -sum * (0.5 / std::numbers::pi) : 0.0;
}

} // namespace radiant::detail
