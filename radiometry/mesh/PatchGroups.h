#pragma once
// Patches grouped into unknowns of about the requested area (issue #20 item 5, step B): a curved,
// finely tessellated surface (a sphere, a rounded cube) has no two coplanar triangles, so the mesher
// leaves one patch per triangle however large --max-patch-area is. A group is a cluster of such
// patches (edge-adjacent, one surface, no crease between them) that shares one radiosity: its form
// factors are summed over its planar pieces (GroupedSolver.h), so every consumer of a patch's
// polygon stays exact and the pieces are drawn with their group's radiosity. The growth is the
// region growing of variational shape approximation (Cohen-Steiner, Alliez, Desbrun, "Variational
// shape approximation", SIGGRAPH 2004) with area, crease and normal-spread bounds in place of its
// planarity metric: a group need not be planar finer than its curvature, only smooth.
#include <cstdint>
#include <span>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

struct GroupingOptions {
    double maxGroupArea = 0.01;      ///< m^2; a group grows while it stays within this
    /// Patches across an edge whose normals differ by more than this are never in one group: a
    /// cube's edge or a cylinder's rim stays a border (a 32-segment sphere's facets differ by 11 deg).
    double creaseDegrees = 30;
    /// Every patch of a group within this of its seed's normal as it grows, and of the joint mean
    /// normal when two groups merge: one radiosity stands for surfaces that face about one way (a
    /// sphere is then at least 4 groups; a cube's sides stay apart by the crease).
    double spreadDegrees = 60;
    /// Below 1, a surface is grouped only where its faces' mean area is at most this fraction of
    /// maxGroupArea (its triangles, not the request, set its patches) and its groups are at most
    /// this fraction of its patches; others stay one group per patch (as ungroupedPatches). 1 groups
    /// every smooth surface (--group-patches); the default grouping takes 0.5 (DefaultGrouping.h).
    double keepAtMostFraction = 1;
    /// A surface of fewer faces is not grouped (a box's sides, a lamp: shapes of their own, whose
    /// patches the request sets); 0 groups any.
    std::uint32_t minimumFaces = 0;
};

struct PatchGroups {
    std::vector<std::uint32_t> groupOf;      ///< patch -> its group
    std::vector<std::uint32_t> firstMember;  ///< group g's patches: members[firstMember[g], firstMember[g + 1])
    std::vector<std::uint32_t> members;      ///< patch indices, grouped, increasing within a group
    std::vector<double> area;                ///< m^2 per group: the sum of its patches'
    std::vector<std::uint32_t> surfaceFirstGroup;  ///< groups of surface s: [surfaceFirstGroup[s], [s + 1])

    [[nodiscard]] std::size_t size() const { return area.size(); }
    [[nodiscard]] std::span<const std::uint32_t> patchesOf(std::size_t group) const {
        return {members.data() + firstMember[group], members.data() + firstMember[group + 1]};
    }
};

/// Groups the mesh's patches surface by surface. Throws RadiantError for a maximum area or angle
/// that is not positive and finite.
PatchGroups groupPatches(const PatchMesh& mesh, const GroupingOptions& options);

/// One group per patch (the ungrouped system, for comparisons).
PatchGroups ungroupedPatches(const PatchMesh& mesh);

} // namespace radiant
