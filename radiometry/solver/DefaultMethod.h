#pragma once
// The method a front end uses when the user names none: Gauss-Seidel (kSolveDefaults.method, the
// accurate one) while its form-factor matrix is small, hierarchical beyond. The matrix grows as n^2
// in memory and its hemicubes as n in time; a room of ten thousand patches would spend a minute and
// a gigabyte before the first picture, and a classroom would be refused. `radiant solve`, `probe`,
// `render` and the lab all decide here, so they agree. An explicit --method or a method picked in
// the Solver panel always wins.
#include <cstddef>
#include <string>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/SolverMethods.h"

namespace radiant {

/// Above this many patches the default is hierarchical: Gauss-Seidel's form factors grow as n^2 (29 s
/// at 2,166 patches, 109 s at 4,056 on the loaded 2-core machine) while hierarchical converges in 5 s
/// at either; 3,000 allows about twice the Cornell box default's wait (2,170 patches), which its
/// accuracy pays for. Measurements in docs/ARCHITECTURE.md, "Defaults".
inline constexpr std::size_t kMatrixMethodMaxPatches = 3000;

struct MethodChoice {
    SolverMethod method;
    /// Why, for people: "12,000 patches: a Gauss-Seidel matrix would need up to 2 GB and ...".
    std::string reason;
};

/// The default method for a mesh of `patches` patches under a matrix budget of `matrixBudgetBytes`
/// (SolverOptions::matrixBudgetBytes): the matrix method while it has at most
/// kMatrixMethodMaxPatches patches and fits the budget, hierarchical otherwise.
[[nodiscard]] MethodChoice chooseDefaultMethod(std::size_t patches, double matrixBudgetBytes);
/// The same from the patch count meshScene(scene, meshing) will make (estimatePatchCount: exact).
[[nodiscard]] MethodChoice chooseDefaultMethod(const Scene& scene, const MeshingOptions& meshing,
                                               double matrixBudgetBytes);

} // namespace radiant
