#pragma once
// A distant source of uniform radiance L that subtends a small solid angle omega (the Sun seen from a
// planet): every direction within omega arrives at nearly the same incidence theta, so
//
//   E = integral over omega of L cos(theta') d omega' ~ L omega cos(theta)   (= L omega at normal incidence).
#include <algorithm>
#include <cmath>

#include "radiometry/units/Angle.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

/// E = L omega cos(theta); 0 when the source is below the horizon (theta >= pi/2).
inline Irradiance distantSourceIrradiance(Radiance radiance, SolidAngle subtended, Radians incidence = Radians(0.0)) {
    return radiance * subtended * std::max(0.0, std::cos(incidence.value()));
}

} // namespace radiant
