#pragma once
// The one table of radiosity methods: every list of methods in the program (the Solver panel, the
// command line's help and errors, the bench, the tests) iterates it, so a new method is its own
// files plus one row here and one enumerator below.
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace radiant {

enum class SolverMethod { Jacobi, GaussSeidel, Progressive, Hierarchical, Importance };

class Solver;
struct Scene;
struct PatchMesh;
struct SolverOptions;
struct Progress;

/// What a method does, for the UI to show what applies to it.
struct SolverTraits {
    bool formFactorMatrix = false;  ///< gathers over a stored patch-to-patch matrix (its size limits the mesh)
    bool shoots = false;            ///< distributes unshot power from one shooter per step
    bool links = false;             ///< refines a hierarchy of elements joined by links
    bool viewDependent = false;     ///< refines where a camera sees
};

using MethodFactory = std::unique_ptr<Solver> (*)(const Scene&, const PatchMesh&, const SolverOptions&, Progress*);

struct SolverMethodInfo {
    SolverMethod method;
    std::string_view name;      ///< on the command line: "gauss-seidel"
    std::string_view label;     ///< as people say it: "Gauss-Seidel"
    std::string_view residual;  ///< what IterationStats::residual measures for this method
    SolverTraits traits;
    MethodFactory factory;
};

/// Every method, in the order a course teaches them.
std::span<const SolverMethodInfo> solverMethods();
const SolverMethodInfo& methodInfo(SolverMethod method);
/// "jacobi, gauss-seidel, progressive, hierarchical or importance": for help and error texts.
std::string methodNameList();

} // namespace radiant
