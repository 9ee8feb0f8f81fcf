#pragma once
// Delta form factors of the hemicube, from M. F. Cohen and D. P. Greenberg, "The Hemi-Cube: A
// Radiosity Solution for Complex Environments", SIGGRAPH 1985.
//
// A half-cube of half-width 1 stands on the point x, its top face in the plane z = 1 above x's
// normal. The form factor from dx to a small pixel of area dA at position p on a face is
//   dF = cos(theta_x) cos(theta_p) dA / (pi r^2)
// with r = |p|. On the top face cos(theta_x) = cos(theta_p) = 1 / r, on a side face (the plane
// x = 1, say) cos(theta_x) = z / r and cos(theta_p) = 1 / r, so
//   top:  dF = dA / (pi (x^2 + y^2 + 1)^2)
//   side: dF = z dA / (pi (y^2 + z^2 + 1)^2)
// Both are one formula in the pixel's direction d (its centre on a face 1 from x, d_z the component
// along the normal): dF = d_z dA / (pi |d|^4). The pixel's solid angle is dA cos(theta_p) / r^2
// = dA / |d|^3.
#include <glm/vec3.hpp>

namespace radiant {

/// Top face pixel centred at (x, y, 1): dA / (pi (x^2 + y^2 + 1)^2).
double topFaceDeltaFormFactor(double x, double y, double pixelArea);
/// Side face pixel at height z in (0, 1] and horizontal offset y: z dA / (pi (y^2 + z^2 + 1)^2).
double sideFaceDeltaFormFactor(double y, double z, double pixelArea);
/// Any face: d_z dA / (pi |d|^4), d the pixel centre (on a face at distance 1) in x's local frame.
double deltaFormFactor(const glm::dvec3& pixelCentre, double pixelArea);
/// The pixel's solid angle, dA / |d|^3 (sr).
double deltaSolidAngle(const glm::dvec3& pixelCentre, double pixelArea);

} // namespace radiant
