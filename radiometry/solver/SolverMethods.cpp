#include "radiometry/solver/SolverMethods.h"

#include <algorithm>
#include <vector>

#include "radiometry/common/Check.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/solver/Solver.h"
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

constexpr SolverMethodInfo kBuiltinMethods[] = {
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

std::vector<SolverMethodInfo>& methodTable() {
    static std::vector<SolverMethodInfo> table(std::begin(kBuiltinMethods), std::end(kBuiltinMethods));
    return table;
}

} // namespace

std::span<const SolverMethodInfo> solverMethods() { return methodTable(); }

SolverMethodRegistration registerSolverMethod(const SolverMethodInfo& info) {
    std::vector<SolverMethodInfo>& table = methodTable();
    for (const SolverMethodInfo& known : table) {
        RADIANT_CHECK_NE(static_cast<int>(known.method), static_cast<int>(info.method));
        RADIANT_CHECK_NE(known.name, info.name);
    }
    RADIANT_CHECK_NE(info.factory, nullptr);
    table.push_back(info);
    return SolverMethodRegistration(info.method);
}

SolverMethodRegistration::~SolverMethodRegistration() {
    if (!live_) return;
    std::erase_if(methodTable(), [this](const SolverMethodInfo& info) { return info.method == method_; });
}

const SolverMethodInfo& methodInfo(SolverMethod method) {
    for (const SolverMethodInfo& info : methodTable())
        if (info.method == method) return info;
    throw RadiantError({"solver", "method"}, "method " + std::to_string(static_cast<int>(method)) + " is not in the table");
}

std::string methodNameList() {
    std::string list;
    const std::span<const SolverMethodInfo> methods = solverMethods();
    for (std::size_t i = 0; i < methods.size(); ++i) {
        if (i > 0) list += i + 1 == methods.size() ? " or " : ", ";
        list += methods[i].name;
    }
    return list;
}

std::string_view methodName(SolverMethod method) { return methodInfo(method).name; }

SolverMethod parseMethod(std::string_view name) {
    for (const SolverMethodInfo& info : methodTable())
        if (info.name == name) return info.method;
    throw RadiantError({"", "method"}, "unknown method '" + std::string(name) + "' (expected " + methodNameList() + ")");
}

std::unique_ptr<Solver> makeSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                   const SolverOptions& options, Progress* progress) {
    // One BVH for all of the solver's parts (form factors, the lights' shadow rays, eye rays) when
    // the caller has none to share; a factory called directly builds what it needs itself.
    if (options.rays) return methodInfo(method).factory(scene, mesh, options, progress);
    SolverOptions shared = options;
    shared.rays = std::make_shared<const RayCaster>(scene);
    return methodInfo(method).factory(scene, mesh, shared, progress);
}

} // namespace radiant
