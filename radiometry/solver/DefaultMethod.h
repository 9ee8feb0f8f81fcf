#pragma once
// The method a front end uses when the user names none: progressive refinement (kSolveDefaults.method:
// within issue 14's 1% mean / 3% worst of the path tracer on the Cornell box, its steps one patch
// shooting at a time; it was the fastest there until hierarchical radiosity's rows got cheaper,
// which now converges in about a quarter of its time) while the mesh is small, hierarchical beyond. Progressive refinement computes its form
// factors a shooter's row at a time, so it needs no matrix, but its time grows faster than the patch
// count (more shooters, each reaching more receivers); hierarchical radiosity's links grow about
// linearly. A room of ten thousand patches would wait half a minute for progressive refinement.
// `radiant solve`, `probe`, `render` and the lab all decide here, so they agree. An explicit --method
// or a method picked in the Solver panel always wins (a picked matrix method still answers to
// SolverOptions::matrixBudgetBytes).
#include <cstddef>
#include <string>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/SolverMethods.h"

namespace radiant {

/// Above this many patches the default is hierarchical. Measured with `radiant solve cornell-box
/// --method M --max-patch-area A` (wall seconds on the idle 2-core machine, 2026-12-02, bd38714):
/// progressive 0.80 s at 2,805 patches, 1.75 s at 5,304, 4.6 s at 10,124; hierarchical 1.03, 1.79 and
/// 3.37 s. Below the crossing progressive refinement is faster, above it grows faster.
/// docs/ARCHITECTURE.md, "Defaults".
inline constexpr std::size_t kProgressiveMaxPatches = 3000;

struct MethodChoice {
    SolverMethod method;
    /// Why, for people: "12,000 patches: progressive refinement's time grows faster than ...".
    std::string reason;
};

/// The default method for a mesh of `patches` patches: progressive refinement up to
/// kProgressiveMaxPatches, hierarchical beyond.
[[nodiscard]] MethodChoice chooseDefaultMethod(std::size_t patches);
/// The same from the patch count meshScene(scene, meshing) will make (estimatePatchCount: exact).
[[nodiscard]] MethodChoice chooseDefaultMethod(const Scene& scene, const MeshingOptions& meshing);
/// With patch groups (PatchGroups.h) the groups are the unknowns, and progressive refinement's shots
/// follow them, not the patches (GroupedSolver.h): progressive refinement over the groups, whatever
/// their count, since hierarchical radiosity refines its own elements and takes no groups (beyond
/// kProgressiveMaxPatches groups the reason says so).
[[nodiscard]] MethodChoice chooseDefaultMethodForGroups(std::size_t groups, std::size_t patches);

} // namespace radiant
