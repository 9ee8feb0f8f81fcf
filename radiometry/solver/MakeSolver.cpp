#include "radiometry/common/Error.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {
struct MethodEntry {
    SolverMethod method;
    std::string_view name;
};
constexpr MethodEntry kMethods[] = {
    {SolverMethod::Jacobi, "jacobi"},
    {SolverMethod::GaussSeidel, "gauss-seidel"},
    {SolverMethod::Progressive, "progressive"},
    {SolverMethod::Hierarchical, "hierarchical"},
    {SolverMethod::Importance, "importance"},
};
} // namespace

std::string_view methodName(SolverMethod method) {
    for (const auto& entry : kMethods)
        if (entry.method == method) return entry.name;
    return "unknown";
}

SolverMethod parseMethod(std::string_view name) {
    for (const auto& entry : kMethods)
        if (entry.name == name) return entry.method;
    throw RadiantError({"", "--method"}, "unknown method '" + std::string(name) +
                                             "' (expected jacobi, gauss-seidel, progressive, hierarchical or importance)");
}

std::unique_ptr<Solver> makeSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                   const SolverOptions& options, Progress* progress) {
    switch (method) {
    case SolverMethod::Jacobi: return makeJacobiSolver(scene, mesh, options, progress);
    case SolverMethod::GaussSeidel: return makeGaussSeidelSolver(scene, mesh, options, progress);
    case SolverMethod::Progressive: return makeProgressiveSolver(scene, mesh, options, progress);
    case SolverMethod::Hierarchical: return makeHierarchicalSolver(scene, mesh, options, progress);
    case SolverMethod::Importance: return makeImportanceSolver(scene, mesh, options, progress);
    }
    throw RadiantError({}, "unknown solver method");
}

} // namespace radiant
