#pragma once
// Whether the patches are grouped into unknowns (PatchGroups.h, GroupedSolver.h) and by which
// method the system is solved, decided once for `radiant solve`, `probe`, `render` and the lab
// (issue #20 item 5). A finely tessellated surface (a sphere, a subdivided rounded box) is one patch
// per triangle however large the requested patch area; grouped, its unknowns follow the request.
// By default a surface of at least 16 faces is grouped where they average at most half the request
// and grouping at least halves its patches, so a scene of large quads (the Cornell box, the furnace), whose faces
// the mesher cuts to the request, is never grouped and solves exactly as without grouping. Beyond kProgressiveMaxPatches groups the default
// solves the patches hierarchically instead (DefaultMethod.h: faster there, and it takes no groups).
// Asked for (--group-patches) every smooth surface is grouped; asked not to (--no-group-patches, the
// lab's box unticked), none. A method that cannot solve groups (hierarchical and importance refine
// their own elements) solves the patches and the reason says so, never an error.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/SolverMethods.h"

namespace radiant {

enum class GroupingMode {
    Auto,  ///< group the surfaces tessellated finer than the request, where that halves their patches
    On,    ///< group every smooth surface (--group-patches)
    Off,   ///< every patch its own unknown (--no-group-patches, the lab's box unticked)
};

/// By default a surface is grouped where its faces' mean area is at most this fraction of the
/// request and its groups at most this fraction of its patches (GroupingOptions::keepAtMostFraction):
/// where its triangles, not the requested area, set its patches. The flat-region merge keeps its
/// faces by the same half (FlatRegions.cpp).
inline constexpr double kGroupWhereAtMost = 0.5;

/// By default a surface of fewer faces is never grouped (GroupingOptions::minimumFaces): the Cornell
/// box's ceiling of 8 quads around its light, its floor (one face the mesher cuts along the blocks)
/// and a box's sides are shapes of their own at any patch area, not a tessellation.
inline constexpr std::uint32_t kMinimumFacesToGroup = 16;

/// Jacobi, Gauss-Seidel and progressive refinement solve groups (makeGroupedSolver).
[[nodiscard]] bool methodTakesGroups(SolverMethod method);

struct SystemChoice {
    /// The unknowns: null when every patch is its own.
    std::shared_ptr<const PatchGroups> groups;
    /// Why grouped or not, for people: "on: 3,103 patches in 75 groups (...)".
    std::string groupingReason;
    /// The named method cannot solve the groups the request would have made: the patches are
    /// solved, and groupingReason says so (a note, not an error).
    bool methodTakesNoGroups = false;
    /// The named method (empty reason), else the default for the unknowns.
    MethodChoice method;
};

/// The groups and the method for `mesh` meshed at `maxPatchArea` (m^2). `named` is the method the
/// user chose, if any. Throws RadiantError for an area that is not positive and finite.
[[nodiscard]] SystemChoice chooseSystem(const PatchMesh& mesh, double maxPatchArea, GroupingMode mode,
                                        std::optional<SolverMethod> named);

} // namespace radiant
