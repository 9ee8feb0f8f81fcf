#pragma once
// Shooters for progressive refinement: groups of adjacent patches of one face that shoot together,
// while every patch still receives on its own - the patches and elements of
//   M. F. Cohen, D. P. Greenberg, D. S. Immel, P. J. Brock, "An efficient radiosity approach for
//   realistic image synthesis", IEEE Computer Graphics and Applications 6(3), 1986.
// A group shoots its members' unshot power sum_i A_i dB_i in one pass over the receivers for k x k
// patches, so the shot count needed for a residual falls by about the group size; each member's
// light still leaves from that member (the shot's kernel weighs each member by its share of the
// power, ProgressiveShot.cpp), and light reaching a receiver is resolved per patch.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

struct ProgressiveShooters {
    std::vector<std::uint32_t> first;    ///< group g holds members[first[g], first[g + 1]); size groups + 1
    std::vector<std::uint32_t> members;  ///< patch indices, each exactly once
    /// The union of each group's patches as one planar convex polygon (metres), when built from a
    /// mesh; empty for groups given without geometry.
    std::vector<PatchPolygon> polygons;
    std::vector<std::uint32_t> surface, face;  ///< of each group's patches, when built from a mesh

    [[nodiscard]] std::size_t size() const { return first.empty() ? 0 : first.size() - 1; }
    [[nodiscard]] std::span<const std::uint32_t> group(std::size_t g) const {
        return {members.data() + first[g], members.data() + first[g + 1]};
    }

    /// Every patch shoots alone (no geometry): classic progressive refinement.
    static ProgressiveShooters eachPatch(std::size_t patchCount);
};

/// Every patch of the mesh shoots alone, with its polygon.
ProgressiveShooters patchShooters(const PatchMesh& mesh);

/// Blocks of at most block x block cells of each face's patch grid (fewer at the grid's far
/// edges): a quad grid's cell is a patch; a triangle lattice is cut into parallelograms of
/// block x block cells (two triangles each), triangles of side block, and a band of parallelograms
/// along its long edge. Patches in no recognised grid shoot alone. block = 1 gives patchShooters.
/// Throws RadiantError for block 0.
ProgressiveShooters blockShooters(const PatchMesh& mesh, std::size_t block);

/// The block side that cuts `patchCount` patches into about `shooters` full blocks (at least 1).
std::size_t blockForShooterCount(std::size_t patchCount, std::size_t shooters);

} // namespace radiant
