#pragma once
// The defaults every front end starts from - `radiant solve`, `probe`, `render` and `bench`, and
// the lab - stated once, here (the README's "Defaults" repeats them for readers).
#include <cstddef>

#include "radiometry/solver/Solver.h"

namespace radiant {

struct SolveDefaults {
    /// While its matrix is small (DefaultMethod.h: chooseDefaultMethod picks hierarchical beyond).
    SolverMethod method = SolverMethod::GaussSeidel;
    /// m^2: 2,170 patches in the Cornell box, where Gauss-Seidel is within 0.74% mean and 1.24%
    /// worst of the path tracer at 10 points; 5.9% / 20% at 0.01 m^2 (260 patches). The table and
    /// the cost (seconds of form factors) are in docs/ARCHITECTURE.md, "Defaults". MeshingOptions'
    /// own 0.01 is the library's, for code that meshes without asking.
    double maxPatchArea = 0.001;
    /// Stop when the method's residual (Solver.h) falls below this.
    double tolerance = 1e-4;
    std::size_t maxIterations = 100000;  ///< a solve that has not converged by then stops and says so
};

inline constexpr SolveDefaults kSolveDefaults{};

} // namespace radiant
