#include "radiometry/solidangle/ClosedFormSolidAngles.h"

#include <cmath>
#include <numbers>
#include <string>

#include "radiometry/common/Error.h"

namespace radiant {

namespace {
[[noreturn]] void reject(const char* where, const std::string& what) { throw RadiantError({"", where}, what); }
} // namespace

SolidAngle smallAreaSolidAngle(Area facingArea, Length distance) {
    if (!(distance.value() > 0) || !(facingArea.value() >= 0))
        reject("A/R^2 solid angle", "needs A >= 0 and R > 0, got A = " + std::to_string(facingArea.value()) +
                                        " m^2, R = " + std::to_string(distance.value()) + " m");
    return SolidAngle(facingArea.value() / (distance.value() * distance.value()));
}

SolidAngle cornerRectangleSolidAngle(Length a, Length b, Length h) {
    const double x = a.value(), y = b.value(), z = h.value();
    if (!(x >= 0) || !(y >= 0) || !(z > 0))
        reject("corner rectangle solid angle", "needs a, b >= 0 and h > 0, got a = " + std::to_string(x) +
                                                   " m, b = " + std::to_string(y) + " m, h = " + std::to_string(z) +
                                                   " m");
    return SolidAngle(std::atan(x * y / (z * std::sqrt(x * x + y * y + z * z))));
}

SolidAngle coneSolidAngle(Radians halfAngle) {
    const double alpha = halfAngle.value();
    if (!(alpha >= 0) || alpha > std::numbers::pi)
        reject("cone solid angle", "half-angle must lie in [0, pi], got " + std::to_string(alpha) + " rad");
    // 1 - cos(alpha) = 2 sin^2(alpha / 2) keeps its digits for narrow cones (the Sun: alpha ~ 4.6e-3).
    const double s = std::sin(0.5 * alpha);
    return SolidAngle(4.0 * std::numbers::pi * s * s);
}

SolidAngle regularSolidFaceSolidAngle(int faceCount) {
    switch (faceCount) {
    case 4: case 6: case 8: case 12: case 20:
        return SolidAngle(4.0 * std::numbers::pi / faceCount);
    default:
        reject("regular solid", "the Platonic solids have 4, 6, 8, 12 or 20 faces, got " + std::to_string(faceCount));
    }
}

} // namespace radiant
