// PLACEHOLDER: deleted when the hierarchical and importance solvers land.
#include "radiometry/common/Error.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {
std::unique_ptr<Solver> makeHierarchicalSolver(const Scene&, const PatchMesh&, const SolverOptions&, Progress*) {
    throw RadiantError({}, "the hierarchical solver is not available in this build yet");
}
std::unique_ptr<Solver> makeImportanceSolver(const Scene&, const PatchMesh&, const SolverOptions&, Progress*) {
    throw RadiantError({}, "the importance solver is not available in this build yet");
}
} // namespace radiant
