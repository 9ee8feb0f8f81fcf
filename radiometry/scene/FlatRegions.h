#pragma once
// Exact simplification of the flat parts of a triangle mesh: vertex removal (Schroeder, Zarge and
// Lorensen, "Decimation of triangle meshes", SIGGRAPH 1992) restricted to vertices whose removal
// leaves the geometry as it was, followed by Lawson's edge flips between coplanar triangles.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace radiant::detail {

using Triangle = std::array<std::uint32_t, 3>;

/// Removes, until none is left, every vertex that is
///  - inside a flat region: its triangles form one closed fan, all coplanar;
///  - on a straight crease: its closed fan is two coplanar runs whose two border edges are collinear;
///  - on a straight border: its fan is one open coplanar run whose two border edges are collinear,
/// triangulating each run's hole by ear clipping in the run's plane (the fattest ear first), then
/// flips coplanar pairs (one of them new) whose other diagonal gives a larger smallest angle; where
/// nothing was removed the triangles come back as given, in their order. Coplanar means unit
/// normals within `coplanarCosine`, collinear within the same angle. A removal that would not keep
/// the mesh manifold and its area (a non-simple hole, an edge that already exists) is skipped.
/// Triangles are counter-clockwise index triples into `points`, which are welded (one index per
/// position); the result indexes the same points.
std::vector<Triangle> removeFlatVertices(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
                                         double coplanarCosine);

} // namespace radiant::detail
