#include "radiometry/sources/PointSource.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant {

Intensity isotropicIntensity(Power power) {
    if (!(power.value() >= 0))
        throw RadiantError({"", "point source"}, "power must be >= 0 W, got " + std::to_string(power.value()));
    return Intensity(power.value() / (4.0 * std::numbers::pi));
}

Irradiance pointSourceIrradiance(Intensity intensity, Length distance, Radians incidence) {
    const double r = distance.value();
    if (!(r > 0))
        throw RadiantError({"", "point source"}, "distance must be > 0 m, got " + std::to_string(r));
    // cos(theta) / r^2 is the solid angle per unit receiving area (sr/m^2) the source sees.
    const double cosTheta = std::max(0.0, std::cos(incidence.value()));
    return Irradiance(intensity.value() * cosTheta / (r * r));
}

Irradiance pointSourceIrradiance(Intensity intensity, const glm::dvec3& source, const glm::dvec3& x,
                                 const glm::dvec3& n) {
    const glm::dvec3 toSource = source - x;
    const double r = glm::length(toSource);
    if (!(r > 0)) throw RadiantError({"", "point source"}, "the receiving point coincides with the source");
    const double cosTheta = std::max(0.0, glm::dot(toSource / r, glm::normalize(n)));
    return Irradiance(intensity.value() * cosTheta / (r * r));
}

} // namespace radiant
