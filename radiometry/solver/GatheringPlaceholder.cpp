// PLACEHOLDER: deleted when the Jacobi, Gauss-Seidel and progressive solvers land.
#include "radiometry/common/Error.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {
std::unique_ptr<Solver> makeJacobiSolver(const Scene&, const PatchMesh&, const SolverOptions&, Progress*) {
    throw RadiantError({}, "the Jacobi solver is not available in this build yet");
}
std::unique_ptr<Solver> makeGaussSeidelSolver(const Scene&, const PatchMesh&, const SolverOptions&, Progress*) {
    throw RadiantError({}, "the Gauss-Seidel solver is not available in this build yet");
}
std::unique_ptr<Solver> makeProgressiveSolver(const Scene&, const PatchMesh&, const SolverOptions&, Progress*) {
    throw RadiantError({}, "the progressive solver is not available in this build yet");
}
} // namespace radiant
