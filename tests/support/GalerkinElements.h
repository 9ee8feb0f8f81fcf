#pragma once
// Elements for the Galerkin basis's tests, built here from corners (independently of the mesher):
// a square, a non-square parallelogram, a trapezoid (a general planar quad, as the Cornell box's
// floor is to 0.6%) and a scalene triangle, each turned into a tilted plane so that no axis lines up
// with the element's edges.
#include <array>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "radiometry/mesh/ElementTree.h"

namespace radiant::test {

/// (x, y) in a plane tilted about two axes, offset from the origin.
inline glm::dvec3 tiltedPlanePoint(double x, double y) {
    const glm::dvec3 e1 = glm::normalize(glm::dvec3(0.8, 0.36, 0.48));
    const glm::dvec3 e2 = glm::normalize(glm::cross(glm::dvec3(0.1, 0.2, 1.0), e1));
    return glm::dvec3(0.3, -0.2, 0.7) + x * e1 + y * e2;
}

inline PatchPolygon tiltedElement(std::span<const std::array<double, 2>> corners) {
    std::array<glm::dvec3, 4> points{};
    for (std::size_t i = 0; i < corners.size(); ++i) points[i] = tiltedPlanePoint(corners[i][0], corners[i][1]);
    return makeElementPolygon({points.data(), corners.size()});
}

inline PatchPolygon tiltedSquare() {
    static constexpr std::array<std::array<double, 2>, 4> corners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    return tiltedElement(corners);
}
inline PatchPolygon tiltedParallelogram() {
    static constexpr std::array<std::array<double, 2>, 4> corners{{{0, 0}, {2, 0}, {2.7, 1.3}, {0.7, 1.3}}};
    return tiltedElement(corners);
}
inline PatchPolygon tiltedTrapezoid() {
    static constexpr std::array<std::array<double, 2>, 4> corners{{{0, 0}, {1, 0}, {0.8, 0.7}, {0.1, 0.55}}};
    return tiltedElement(corners);
}
inline PatchPolygon tiltedTriangle() {
    static constexpr std::array<std::array<double, 2>, 3> corners{{{0, 0}, {1.5, 0.2}, {0.4, 1.1}}};
    return tiltedElement(corners);
}

/// The bilinear (quad) or affine (triangle) map of the corners, written out here for the tests.
inline glm::dvec3 mapOfCorners(const PatchPolygon& e, double u, double v) {
    const auto& p = e.vertices;
    if (e.count == 3) return p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
    return (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
}

/// dA / (du dv) by central differences of mapOfCorners (independent of Basis.cpp's closed form).
inline double jacobianByDifferences(const PatchPolygon& e, double u, double v) {
    const double h = 1e-6;
    const glm::dvec3 xu = (mapOfCorners(e, u + h, v) - mapOfCorners(e, u - h, v)) / (2 * h);
    const glm::dvec3 xv = (mapOfCorners(e, u, v + h) - mapOfCorners(e, u, v - h)) / (2 * h);
    return glm::length(glm::cross(xu, xv));
}

} // namespace radiant::test
