#pragma once
// The method a front end uses when the user names none: progressive refinement (kSolveDefaults.method:
// within issue 14's 1% mean / 3% worst of the path tracer on the Cornell box and the fastest there to
// converge) while the mesh is small, hierarchical beyond. Progressive refinement computes its form
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
/// --method M --max-patch-area A` (CPU seconds, 2026-12-02): progressive 1.35 s at 2,805 patches,
/// 3.4 s at 5,304, 9.2 s at 10,124; hierarchical 0.13, 0.12 and 0.18 s. 3,000 keeps the lab's
/// opening on the Cornell box default (2,805 patches) at about a second. docs/ARCHITECTURE.md,
/// "Defaults".
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

} // namespace radiant
