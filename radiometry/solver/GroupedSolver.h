#pragma once
// The radiosity system over groups of patches (PatchGroups.h): one unknown per group, patches keep
// their planar polygons. With B constant over a group C (area A_C = sum of its patches' A_p),
//   B_C = E_C + rho_C sum_D F_CD B_D,   F_CD = (1 / A_C) sum_{p in C} sum_{q in D} A_p F_pq,
// the area-weighted mean of its patches' rows (Cohen and Wallace, "Radiosity and Realistic Image
// Synthesis", 1993, sec. 8.3: the form factor of an element group). Each F_pq is the existing exact
// patch-to-patch factor, so a closed surface's rows still sum to 1; a curved group sees itself
// (F_CC > 0 inside a sphere). The matrix holds one row per group, so its size and the solve follow
// the requested area; its computation still visits every pair of patches.
#include <memory>

#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/solver/SolverCommon.h"

namespace radiant {

/// F_CD for every pair of groups (including C = D), in parallel over patches, reporting progress in
/// patch pairs and honouring cancellation. Entries below `threshold` are dropped.
FormFactorMatrix computeGroupedFormFactors(const PatchMesh& mesh, const PatchGroups& groups, const RayCaster* rays,
                                           const FormFactorOptions& options, double threshold,
                                           Progress* progress = nullptr);

/// Per-group area, material and the lights' direct irradiance (its patches' area-weighted mean).
PatchMaterials groupedMaterials(const Scene& scene, const PatchMesh& mesh, const PatchGroups& groups,
                                const RayCaster* rays = nullptr);

/// A Jacobi or Gauss-Seidel solver of the grouped system whose solution() is per patch, each patch
/// holding its group's radiosity, so the probe, the renderer and the reports take it as any
/// solution. Throws RadiantError for another method (they keep their own patch or element systems).
std::unique_ptr<Solver> makeGroupedSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                          std::shared_ptr<const PatchGroups> groups, const SolverOptions& options,
                                          Progress* progress = nullptr);

} // namespace radiant
