#include "radiometry/solver/SolverMethods.h"

#include "radiometry/common/Error.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

// Relative to the power the scene emits, so one tolerance means the same for every scene.
constexpr std::string_view kMatrixResidual =
    "residual of B = E + rho F B: max over bands of sum_i A_i |B_i - E_i - rho_i sum_j F_ij B_j| / "
    "sum_i A_i E_i";
constexpr std::string_view kUnshot = "unshot power / emitted power (max over bands); it bounds the matrix residual";
constexpr std::string_view kSweepChange =
    "change in the last sweep: max over bands of sum over leaves A |B_new - B_old| / sum A E";

constexpr SolverMethodInfo kMethods[] = {
    {SolverMethod::Jacobi, "jacobi", "Jacobi", kMatrixResidual, {.formFactorMatrix = true}, makeJacobiSolver},
    {SolverMethod::GaussSeidel, "gauss-seidel", "Gauss-Seidel", kMatrixResidual, {.formFactorMatrix = true},
     makeGaussSeidelSolver},
    {SolverMethod::Progressive, "progressive", "Progressive refinement", kUnshot, {.shoots = true},
     makeProgressiveSolver},
    {SolverMethod::Hierarchical, "hierarchical", "Hierarchical", kSweepChange, {.links = true},
     makeHierarchicalSolver},
    {SolverMethod::Importance, "importance", "Importance-driven", kSweepChange,
     {.links = true, .viewDependent = true}, makeImportanceSolver},
};

} // namespace

std::span<const SolverMethodInfo> solverMethods() { return kMethods; }

const SolverMethodInfo& methodInfo(SolverMethod method) {
    for (const SolverMethodInfo& info : kMethods)
        if (info.method == method) return info;
    throw RadiantError({"solver", "method"}, "method " + std::to_string(static_cast<int>(method)) + " is not in the table");
}

std::string methodNameList() {
    std::string list;
    const std::size_t count = std::size(kMethods);
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) list += i + 1 == count ? " or " : ", ";
        list += kMethods[i].name;
    }
    return list;
}

std::string_view methodName(SolverMethod method) { return methodInfo(method).name; }

SolverMethod parseMethod(std::string_view name) {
    for (const SolverMethodInfo& info : kMethods)
        if (info.name == name) return info.method;
    throw RadiantError({"", "method"}, "unknown method '" + std::string(name) + "' (expected " + methodNameList() + ")");
}

std::unique_ptr<Solver> makeSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                   const SolverOptions& options, Progress* progress) {
    return methodInfo(method).factory(scene, mesh, options, progress);
}

} // namespace radiant
