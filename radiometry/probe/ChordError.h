#pragma once
// How far a curved surface's tessellation may lie from the smooth surface it stands for (its chord
// error), face by face, so that a point named on the smooth surface (a sphere's equator from its
// equation, a point read off another program) is read on the facet below it instead of refused.
//
// Estimated from the mesh alone. Across an edge shared with a face of the same surface that turns by
// theta (0 < theta <= kCurvedTurnRadians) over a centroid distance d, the surface bends with
// curvature kappa = theta / d (the largest of the face's edges counts). A facet inscribed in a sphere
// of radius 1 / kappa, its corners on a circle of radius r, is within the sagitta kappa r^2 / 2 of
// it (to first order), at that circle's centre. A face is part of a curved tessellation when two or more of
// its edges turn so: a sphere's or a cylinder's facets are, a box's faces (90 degrees) or a roof's
// (one ridge) are not, and a flat floor's coplanar faces turn by nothing.
#include <vector>

#include "radiometry/scene/Scene.h"

namespace radiant {

/// The largest turn between neighbouring faces that still approximates a curve, not a crease:
/// Blender's UV sphere and cylinder turn by 11.25 degrees, a 12-sided cylinder by 30.
inline constexpr double kCurvedTurnRadians = 0.5236;  // 30 degrees

/// Chord error per face (m), indexed [surface][face]; 0 for faces that are not part of a curved
/// tessellation. Edges are matched by their corners' exact positions (the loader welds vertices).
[[nodiscard]] std::vector<std::vector<double>> tessellationChordErrors(const Scene& scene);

} // namespace radiant
