#pragma once
// The radiosity system over groups of patches (PatchGroups.h): one unknown per group, patches keep
// their planar polygons. With B constant over a group C (area A_C = sum of its patches' A_p),
//   B_C = E_C + rho_C sum_D F_CD B_D,   F_CD = (1 / A_C) sum_{p in C} sum_{q in D} A_p F_pq,
// the area-weighted mean of its patches' rows (Cohen and Wallace, "Radiosity and Realistic Image
// Synthesis", 1993, sec. 8.3: the form factor of an element group). Each F_pq is the existing exact
// patch-to-patch factor, so a closed surface's rows still sum to 1; a curved group sees itself
// (F_CC > 0 inside a sphere). The matrix holds one row per group, so its size and the solve follow
// the requested area; its computation still visits every pair of patches. Progressive refinement
// shoots group by group with the same F_CD computed a column at a time, without a matrix.
#include <memory>

#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/ProgressiveSolver.h"
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

/// Progressive refinement's shooters over groups (members are group indices): where the mesh's
/// block shooters (ProgressiveShooters.h, `block` cells a side) hold whole groups only - a flat
/// wall's patches, each its own group at the requested area - the block shoots them together, with
/// its outline; every other group shoots alone, with no outline (polygons[s].count == 0) unless it
/// is one patch. Without blocks, a wall of single-patch groups took a shot per patch (2,051 shots
/// against 1,715 ungrouped for tests/data/grouping/sphere_room.gltf at 0.2 m^2).
ProgressiveShooters groupShooters(const PatchMesh& mesh, const PatchGroups& groups, std::size_t block);

/// Progressive refinement's shots over groups (Cohen, Chen, Wallace, Greenberg, SIGGRAPH 1988, with
/// groups as the unknowns): shooter S's shot fills toShooter[D] = F_{D->S}, its patches' F_{q->S}
/// gathered by area. A block shooter's F_{q->S} is the patch shooters' block kernel (each group's
/// share of the power spread over its area); a lone group's is sum_{p in C} F_{q->p}, each member's
/// exact kernel averaged over the receiving patch, times ray-cast visibility to points spread over
/// its members by area, each ray judged by its own member's normal (ProgressiveShot.cpp). A lone
/// group's shot visits every patch against each of its members, so a sweep costs what the patch
/// pairs cost; the shots to converge follow the shooters.
GroupShotFormFactors makeRayCastPatchGroupShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                                          std::shared_ptr<const PatchGroups> groups,
                                                          const ProgressiveShooters& shooters, const SolverOptions& options);

/// A Jacobi, Gauss-Seidel or progressive solver of the grouped system whose solution() is per
/// patch, each patch holding its group's radiosity, so the probe, the renderer and the reports take
/// it as any solution; a shot's IterationStats::shooter is the shooting group's first patch.
/// Throws RadiantError for another method (hierarchical and importance refine their own elements).
std::unique_ptr<Solver> makeGroupedSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                          std::shared_ptr<const PatchGroups> groups, const SolverOptions& options,
                                          Progress* progress = nullptr);

} // namespace radiant
