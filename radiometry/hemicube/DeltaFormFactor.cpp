#include "radiometry/hemicube/DeltaFormFactor.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace radiant {

double topFaceDeltaFormFactor(double x, double y, double pixelArea) {
    const double s = x * x + y * y + 1.0;
    return pixelArea / (std::numbers::pi * s * s);
}

double sideFaceDeltaFormFactor(double y, double z, double pixelArea) {
    const double s = y * y + z * z + 1.0;
    return z * pixelArea / (std::numbers::pi * s * s);
}

double deltaFormFactor(const glm::dvec3& pixelCentre, double pixelArea) {
    const double r2 = glm::dot(pixelCentre, pixelCentre);
    return pixelCentre.z * pixelArea / (std::numbers::pi * r2 * r2);
}

double deltaSolidAngle(const glm::dvec3& pixelCentre, double pixelArea) {
    const double r = glm::length(pixelCentre);
    return pixelArea / (r * r * r);
}

} // namespace radiant
