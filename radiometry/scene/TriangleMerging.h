#pragma once
// Triangles to faces: exporters write every wall as triangles, and a subdivided model writes a flat
// wall as hundreds of them; radiosity wants the wall's outline back, so that the mesher cuts it into
// patches of the requested size rather than keeping every triangle as at least one patch.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant::detail {

/// Faces of one primitive's triangles (counter-clockwise index triples into `positions`; vertices
/// are matched by position). With `removeFlat`, first every vertex whose triangles are
/// coplanar (a flat region's inside), or lies on a straight line between two flat regions or on a
/// straight border, is removed and its hole triangulated in the plane, and coplanar triangles are
/// flipped towards Delaunay's (the largest smallest angle): the geometry, its area and its
/// closedness are unchanged and the triangulation stays conforming (no T-junction), but a flat
/// region keeps only the corners of its outline; the grouped faces are kept where they are at most
/// half as many as the given ones. Then coplanar triangles sharing an edge are paired into convex
/// quads where the pair forms one (strictly convex, so no corner is dropped; grouped, only quads
/// with opposite sides within 3:1); the rest stay triangles.
std::vector<Face> mergeTriangles(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                 bool removeFlat = true);

} // namespace radiant::detail
