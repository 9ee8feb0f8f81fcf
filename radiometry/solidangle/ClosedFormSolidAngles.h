#pragma once
// Solid angles with closed forms, from the lecture and the radiation heat-transfer literature
// (Siegel & Howell, Thermal Radiation Heat Transfer). They are the oracles for the exact polygon
// solid angle (PolygonSolidAngle.h) and the formulas a class checks by hand.
#include "radiometry/units/Angle.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

/// Omega ~ A / R^2 (the lecture's definition): a small area facing the point at distance R. Good
/// only when the area's size is small against R; overestimates when close (it grows without bound
/// where the true solid angle stays below 2 pi). Throws RadiantError when R <= 0 or A < 0.
SolidAngle smallAreaSolidAngle(Area facingArea, Length distance);

/// Rectangle a x b seen from height h above one of its corners:
/// Omega = atan(a b / (h sqrt(a^2 + b^2 + h^2))). Throws RadiantError unless a, b >= 0 and h > 0.
SolidAngle cornerRectangleSolidAngle(Length a, Length b, Length h);

/// Cone (spherical cap) of half-angle alpha in [0, pi]: Omega = 2 pi (1 - cos alpha).
SolidAngle coneSolidAngle(Radians halfAngle);

/// One face of a regular solid with n faces seen from its centre: 4 pi / n (a dodecahedron's face:
/// 1.047 sr, the lecture's "1 sr"). Throws RadiantError unless n is 4, 6, 8, 12 or 20.
SolidAngle regularSolidFaceSolidAngle(int faceCount);

/// The whole sphere, 4 pi sr, and the hemisphere, 2 pi sr.
inline constexpr SolidAngle kSphereSolidAngle{12.566370614359172};
inline constexpr SolidAngle kHemisphereSolidAngle{6.283185307179586};
/// The hemisphere's projected solid angle, integral of cos(theta) d omega = pi sr: why B = pi L.
inline constexpr SolidAngle kHemisphereProjectedSolidAngle{3.141592653589793};

} // namespace radiant
