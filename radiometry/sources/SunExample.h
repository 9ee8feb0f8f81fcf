#pragma once
// The lecture's Sun example (K. Bala, "Radiometry and Rendering Equation", Cornell CS 2004), as data
// a lecture-demo panel can show next to the formulas, and the two routes to the irradiance on Earth:
//
//   The lecture's route: L = P / (pi A) = 2.05e7 W/(m^2 sr), then E = L omega with its rounded solid
//   angles (Earth 6.7e-5 sr -> 1373.5 W on 1 m^2; Mars 2.92e-5 sr -> 598.6 W).
//   The geometric route: sun radius R = sqrt(A / 4 pi) = 6.95e8 m, omega = pi R^2 / d^2 at
//   d = 1 au = 1.496e11 m (6.78e-5 sr, 1390 W/m^2) and at Mars, 1.524 au. The lecture rounded:
//   the routes differ by about 1.2%.
#include "radiometry/units/Quantity.h"

namespace radiant {

struct SunExample {
    // The lecture's data.
    Power power{3.91e26};                    ///< W radiated by the Sun
    Area surfaceArea{6.07e18};               ///< m^2 of the Sun's surface
    SolidAngle lectureEarthSolidAngle{6.7e-5};   ///< sr, the Sun seen from Earth (as the lecture rounds it)
    SolidAngle lectureMarsSolidAngle{2.92e-5};   ///< sr, the Sun seen from Mars
    Area receiverArea{1.0};                  ///< m^2: "power reaching Earth on a 1 m^2 square", Sun at zenith

    // The geometry behind the solid angles.
    Length astronomicalUnit{1.496e11};       ///< m, mean Earth-Sun distance
    double marsDistanceAu = 1.524;           ///< Mars' mean distance from the Sun, in au

    /// L = P / (pi A): the same radiance leaves the Sun towards Earth and Mars (radiance is invariant
    /// along rays), only the solid angle the Sun subtends differs.
    [[nodiscard]] Radiance radiance() const;
    /// R = sqrt(A / (4 pi)): the Sun as a sphere of the given surface area.
    [[nodiscard]] Length sunRadius() const;
    [[nodiscard]] Length earthDistance() const { return astronomicalUnit; }
    [[nodiscard]] Length marsDistance() const { return astronomicalUnit * marsDistanceAu; }
    /// The lecture's formula: projected area of the Sun over distance squared, pi R^2 / d^2.
    [[nodiscard]] SolidAngle projectedAreaSolidAngle(Length distance) const;
    /// The exact cap the Sun's sphere subtends, 2 pi (1 - cos alpha) with sin alpha = R / d.
    [[nodiscard]] SolidAngle exactSolidAngle(Length distance) const;
    /// E = L omega at normal incidence (W/m^2).
    [[nodiscard]] Irradiance irradiance(SolidAngle sunSolidAngle) const;
    /// P = L A omega on the receiving square (W).
    [[nodiscard]] Power powerOnReceiver(SolidAngle sunSolidAngle) const;
};

} // namespace radiant
