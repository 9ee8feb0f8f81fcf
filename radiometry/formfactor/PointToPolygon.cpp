// Exact, unoccluded form factor from a differential area to a polygon: Lambert's contour integral
// (see LambertKernel.h for the method and its references).
#include <cmath>

#include "radiometry/common/Error.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/formfactor/LambertKernel.h"

namespace radiant {

double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon) {
    const double length = glm::length(n);
    if (!(length > 0) || !std::isfinite(length))
        throw RadiantError({"pointToPolygonFormFactor", "normal"},
                           "the normal must be a finite non-zero vector, got (" + std::to_string(n.x) + ", " +
                               std::to_string(n.y) + ", " + std::to_string(n.z) + ")");
    const glm::dvec3 unitNormal = n / length;
    return detail::formFactorFromLambertSum(detail::clippedLambertSum(x, unitNormal, polygon, polygon.size()));
}

} // namespace radiant
