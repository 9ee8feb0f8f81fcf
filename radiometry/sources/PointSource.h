#pragma once
// An isotropic point source (the lecture's "irradiance example"): its power P spreads evenly over
// spheres around it, so the intensity is I = P / (4 pi sr) and a surface at distance r whose normal
// makes angle theta with the direction to the source receives
//
//   E = I cos(theta) / r^2     (inverse-square law times Lambert's cosine law).
#include <glm/vec3.hpp>

#include "radiometry/units/Angle.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

/// I = P / (4 pi sr). Throws RadiantError for a negative power.
Intensity isotropicIntensity(Power power);

/// E = I cos(theta) / r^2 for incidence angle theta (0 = the source straight above the normal);
/// 0 when theta >= pi/2 (the source is below the surface). Throws RadiantError when r <= 0.
Irradiance pointSourceIrradiance(Intensity intensity, Length distance, Radians incidence);

/// The same from positions: a source at `source`, a receiving point x with unit normal n.
/// Throws RadiantError when the source sits on x.
Irradiance pointSourceIrradiance(Intensity intensity, const glm::dvec3& source, const glm::dvec3& x,
                                 const glm::dvec3& n);

} // namespace radiant
