#pragma once
// Radiosity at a point between patch centres. The solvers give one value per patch (a constant
// basis); the eye and the probe want a continuous field. Nodal averaging (Cohen & Wallace,
// "Radiosity and Realistic Image Synthesis", 1993, section 9.2): each mesh vertex takes the
// area-weighted mean of the patches around it, and a point inside a patch interpolates its corners
// with Wachspress coordinates (E. Wachspress, "A Rational Finite Element Basis", 1975; Meyer, Barr,
// Lee & Desbrun, "Generalized Barycentric Coordinates on Irregular Polygons", JGT 2002): barycentric
// on triangles, bilinear on parallelograms, smooth and positive inside any convex polygon.
// Vertices are shared within a surface only, so values never bleed across a corner of the room.
// Covered patches (Patch::covered) count at a vertex only where no open patch meets: OpenFirstMean.h.
#include <array>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

/// Per mesh vertex, the area-weighted mean radiosity (W/m^2, per band) of the open patches using it,
/// or of the covered ones where no open patch does.
/// Throws RadiantError when the solution's size differs from the mesh's patch count.
std::vector<Rgb> vertexRadiosity(const PatchMesh& mesh, std::span<const Rgb> patchRadiosity);

/// Wachspress coordinates of `point` (taken in the polygon's plane) in a convex polygon of 3 or 4
/// corners counter-clockwise about `normal`; they sum to 1. A point outside is clamped to the border.
std::array<double, 4> wachspressCoordinates(std::span<const glm::dvec3> corners, const glm::dvec3& normal,
                                            const glm::dvec3& point);

/// The interpolated radiosity at `point` on `patch`. Each corner takes the area-weighted mean of the
/// open patches of the same surface that share that corner AND the patch's plane (the covered ones
/// where no open one does), so a value never bleeds
/// around a crease (a block's top into its sides), as the display's smoothing does too.
Rgb interpolateRadiosity(const PatchMesh& mesh, std::span<const Rgb> patchRadiosity, std::size_t patch,
                         const glm::dvec3& point);

/// The interpolated radiosity at `point` on `patch`, from vertexRadiosity()'s values (planar surfaces).
Rgb interpolateRadiosity(const PatchMesh& mesh, std::size_t patch, const glm::dvec3& point,
                         std::span<const Rgb> vertexValues);

} // namespace radiant
