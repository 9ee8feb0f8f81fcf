#pragma once
// Which patch corners share one smoothed (Gouraud) radiosity: corners at the same mesh vertex whose
// patches' normals lie within a small angle of each other. A crease (a block's 90-degree edge) keeps
// its sides apart, because light jumps there; a face split into slightly non-planar triangles (the
// Cornell box's left wall) is smoothed across its diagonal, which a test on exact normals showed as
// a seam. Surfaces share no mesh vertices, so smoothing never crosses from one surface to another.
// GL-free.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant::render {

/// Normals closer than this share vertex radiosity: above the non-planarity of hand-measured
/// quads (a fraction of a degree in the Cornell data), far below any crease meant to be one.
inline constexpr double kSmoothingAngleDegrees = 10.0;

struct SmoothingGroups {
    /// Per patch: the smoothing vertex of each corner (corners beyond cornerCount unused).
    std::vector<std::array<std::uint32_t, 4>> cornerVertex;
    std::vector<std::uint8_t> cornerCount;
    /// Per patch: 1 when covered (Patch::covered); it counts at a smoothing vertex only where no
    /// open patch meets (OpenFirstMean.h, the rule the probe's interpolation shares).
    std::vector<std::uint8_t> covered;
    std::size_t vertexCount = 0;
};

/// Groups each mesh vertex's patch corners: a corner joins the first group at that vertex whose
/// first patch's normal is within `maxAngleDegrees` of its own patch's, else starts a group.
SmoothingGroups findSmoothingGroups(const PatchMesh& mesh, double maxAngleDegrees = kSmoothingAngleDegrees);

/// Per smoothing vertex: the area-weighted mean radiosity of the open patches meeting there, or of
/// the covered ones where no open one does (W/m^2; OpenFirstMean).
/// `patchAreaM2` and `radiosityW_m2` have one entry per patch; `out` is resized to vertexCount.
void smoothRadiosity(const SmoothingGroups& groups, std::span<const double> patchAreaM2,
                     std::span<const Rgb> radiosityW_m2, std::vector<Rgb>& out);

} // namespace radiant::render
