#pragma once
// A diffuse (Lambertian) surface has the same radiance L in every direction. Integrating
// L cos(theta) over the hemisphere gives pi L (the hemisphere's projected solid angle is pi sr), so
//
//   B = pi L          (radiosity or exitance from radiance, and back: L = B / pi)
//   P = pi L A        (the lecture's diffuse emitter: power of an area A, and back: L = P / (pi A))
#include "radiometry/solidangle/ClosedFormSolidAngles.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

constexpr Radiosity radiosityFromRadiance(Radiance radiance) { return radiance * kHemisphereProjectedSolidAngle; }
constexpr Radiance radianceFromRadiosity(Radiosity radiosity) { return radiosity / kHemisphereProjectedSolidAngle; }
constexpr RadiosityRgb radiosityFromRadiance(const RadianceRgb& radiance) {
    return radiance * kHemisphereProjectedSolidAngle;
}
constexpr RadianceRgb radianceFromRadiosity(const RadiosityRgb& radiosity) {
    return radiosity / kHemisphereProjectedSolidAngle;
}

constexpr Power diffuseEmitterPower(Radiance radiance, Area area) {
    return radiance * area * kHemisphereProjectedSolidAngle;
}
constexpr Radiance diffuseEmitterRadiance(Power power, Area area) {
    return power / (area * kHemisphereProjectedSolidAngle);
}

} // namespace radiant
