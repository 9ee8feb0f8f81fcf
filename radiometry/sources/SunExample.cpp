#include "radiometry/sources/SunExample.h"

#include <cmath>
#include <numbers>
#include <string>

#include "radiometry/common/Error.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"
#include "radiometry/sources/DiffuseEmitter.h"
#include "radiometry/sources/DistantSource.h"

namespace radiant {

Radiance SunExample::radiance() const { return diffuseEmitterRadiance(power, surfaceArea); }

Length SunExample::sunRadius() const { return Length(std::sqrt(surfaceArea.value() / (4.0 * std::numbers::pi))); }

SolidAngle SunExample::projectedAreaSolidAngle(Length distance) const {
    const double r = sunRadius().value();
    return smallAreaSolidAngle(Area(std::numbers::pi * r * r), distance);
}

SolidAngle SunExample::exactSolidAngle(Length distance) const {
    const double sinAlpha = sunRadius().value() / distance.value();
    if (!(sinAlpha < 1))
        throw RadiantError({"", "Sun example"}, "a viewer at " + std::to_string(distance.value()) +
                                                    " m is inside the Sun (radius " +
                                                    std::to_string(sunRadius().value()) + " m)");
    return coneSolidAngle(Radians(std::asin(sinAlpha)));
}

Irradiance SunExample::irradiance(SolidAngle sunSolidAngle) const {
    return distantSourceIrradiance(radiance(), sunSolidAngle);
}

Power SunExample::powerOnReceiver(SolidAngle sunSolidAngle) const { return irradiance(sunSolidAngle) * receiverArea; }

} // namespace radiant
