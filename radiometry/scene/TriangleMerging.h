#pragma once
// Triangles to faces: exporters write every wall as triangles; radiosity wants the wall's quads
// back, so that it is meshed into a regular grid rather than slivers.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant::detail {

/// Pairs coplanar triangles sharing an edge into convex quads where the pair forms one (strictly
/// convex, so no corner is dropped and no T-junction appears); the rest stay triangles. Triangles
/// are counter-clockwise index triples into `positions`; vertices are matched by position.
std::vector<Face> mergeTriangles(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles);

} // namespace radiant::detail
