#pragma once
// The exact solid angle a planar polygon subtends at a point, from A. van Oosterom and J. Strackee,
// "The Solid Angle of a Plane Triangle", IEEE Trans. Biomed. Eng. BME-30(2), 1983:
//
//   tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a . b)|c| + (a . c)|b| + (b . c)|a|)
//
// for the vectors a, b, c from the point to a triangle's corners, evaluated with atan2 so that any
// triangle up to a hemisphere comes out right. A polygon is a fan of triangles from its first vertex;
// the signed triangle terms cancel where the fan folds, so the sum is exact for any simple planar
// polygon, convex or not, wherever the point's projection falls (inside, outside, "around" it).
#include <span>

#include <glm/vec3.hpp>

#include "radiometry/units/Quantity.h"

namespace radiant {

/// Signed solid angle of a planar polygon seen from x: positive when x lies on the polygon's front
/// side (the side its counter-clockwise winding's normal points to), negative from behind, 0 when x
/// lies in the polygon's plane (it is seen edge-on). |result| < 2 pi sr.
/// Throws RadiantError for fewer than 3 vertices.
SolidAngle signedPolygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon);

/// The solid angle of the polygon seen from x, from either side: |signedPolygonSolidAngle|.
SolidAngle polygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon);

/// The solid angle of the part of a planar convex polygon above the plane through x with normal n:
/// what a point on a surface can see of it (the part below its horizon is clipped away first,
/// Sutherland-Hodgman). Either side of the polygon counts. Throws RadiantError for a zero normal.
SolidAngle solidAngleAboveHorizon(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon);

/// The signed solid angle of the triangle a, b, c seen from the origin (Van Oosterom & Strackee):
/// positive when the origin lies on the side its normal (b - a) x (c - a) points to.
SolidAngle signedTriangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

} // namespace radiant
