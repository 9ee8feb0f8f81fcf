#pragma once
// The one table of radiosity methods: every list of methods in the program (the Solver panel, the
// command line's help and errors, the bench, the tests) iterates it, so a new method is its own
// files plus one row in SolverMethods.cpp and one enumerator below. A method kept outside the library
// (a test's dummy, which shows that claim holds) joins the table through registerSolverMethod.
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace radiant {

// A fixed underlying type, so a registered method may take any id past the built-in ones.
enum class SolverMethod : int { Jacobi, GaussSeidel, Progressive, Hierarchical, Importance };

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

/// Every method, in the order a course teaches them, then any registered ones.
std::span<const SolverMethodInfo> solverMethods();
const SolverMethodInfo& methodInfo(SolverMethod method);
/// "jacobi, gauss-seidel, progressive, hierarchical or importance": for help and error texts.
std::string methodNameList();

/// Keeps a registered method in the table for as long as it lives (move-only).
class SolverMethodRegistration {
public:
    explicit SolverMethodRegistration(SolverMethod method) : method_(method) {}
    SolverMethodRegistration(SolverMethodRegistration&& other) noexcept : method_(other.method_) { other.live_ = false; }
    SolverMethodRegistration(const SolverMethodRegistration&) = delete;
    SolverMethodRegistration& operator=(const SolverMethodRegistration&) = delete;
    SolverMethodRegistration& operator=(SolverMethodRegistration&&) = delete;
    ~SolverMethodRegistration();

private:
    SolverMethod method_;
    bool live_ = true;
};

/// Adds a method to the table. Its id and name must be new and its strings must outlive the
/// registration. The table is not locked: register before any other thread reads it, and drop the
/// registration only when none does (the spans solverMethods() returned are invalid after either).
[[nodiscard]] SolverMethodRegistration registerSolverMethod(const SolverMethodInfo& info);

} // namespace radiant
