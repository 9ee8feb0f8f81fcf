#pragma once
// The point-to-point kernel of radiative exchange between two Lambertian surfaces.
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace radiant {

/// G(x, y) = cos(theta_x) cos(theta_y) / (pi r^2) without visibility, 1/m^2: zero where y is behind
/// x's surface (unit normal nx) or x behind y's (ny). Integrated over a source's area it is the form
/// factor from a differential area at x.
[[nodiscard]] inline double pointToPointKernel(const glm::dvec3& x, const glm::dvec3& nx, const glm::dvec3& y,
                                               const glm::dvec3& ny) {
    const glm::dvec3 d = y - x;
    const double r2 = glm::dot(d, d);
    const double cosX = glm::dot(nx, d), cosY = -glm::dot(ny, d);  // each times r
    if (!(cosX > 0) || !(cosY > 0)) return 0.0;
    return cosX * cosY / (std::numbers::pi * r2 * r2);
}

} // namespace radiant
