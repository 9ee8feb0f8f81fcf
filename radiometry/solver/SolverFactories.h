#pragma once
// One factory per method, each defined beside its solver; makeSolver() dispatches on the method.
#include <memory>

#include "radiometry/solver/Solver.h"

namespace radiant {

class RayCaster;

std::unique_ptr<Solver> makeJacobiSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                         Progress* progress);
std::unique_ptr<Solver> makeGaussSeidelSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                              Progress* progress);
std::unique_ptr<Solver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                              Progress* progress);
std::unique_ptr<Solver> makeHierarchicalSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                               Progress* progress);
std::unique_ptr<Solver> makeImportanceSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                             Progress* progress);

} // namespace radiant
