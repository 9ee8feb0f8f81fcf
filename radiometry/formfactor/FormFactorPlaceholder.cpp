// PLACEHOLDER: deleted when form factors and ray casting land.
#include "radiometry/common/Error.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"

namespace radiant {
double pointToPolygonFormFactor(const glm::dvec3&, const glm::dvec3&, std::span<const glm::dvec3>) {
    throw RadiantError({}, "form factors not available yet");
}
double formFactor(const PatchPolygon&, const PatchPolygon&, const RayCaster*, const FormFactorOptions&) {
    throw RadiantError({}, "form factors not available yet");
}
double visibilityFraction(const PatchPolygon&, const PatchPolygon&, const RayCaster*, const FormFactorOptions&) {
    throw RadiantError({}, "form factors not available yet");
}
struct RayCaster::Impl {};
RayCaster::RayCaster(const Scene&) { throw RadiantError({}, "ray casting not available yet"); }
RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;
std::optional<RayHit> RayCaster::intersect(const glm::dvec3&, const glm::dvec3&, double) const { return std::nullopt; }
bool RayCaster::occluded(const glm::dvec3&, const glm::dvec3&) const { return false; }
} // namespace radiant
