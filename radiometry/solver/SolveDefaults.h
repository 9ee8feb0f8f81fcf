#pragma once
// The defaults every front end starts from - `radiant solve`, `probe`, `render` and `bench`, and
// the lab - stated once, here (the README's "Defaults" repeats them for readers).
#include <cstddef>

#include "radiometry/solver/Solver.h"

namespace radiant {

struct SolveDefaults {
    SolverMethod method = SolverMethod::GaussSeidel;
    /// m^2: 2,170 patches in the Cornell box, where Gauss-Seidel is within 0.7% mean and 2.3%
    /// worst of a path tracer at points (issue 14's measurement at ~2,100 patches); at 0.01 m^2
    /// (260 patches) it was 4.5% / 21%, and the probe's "M + rho E" check 16-23% off on the floor.
    /// (MeshingOptions' own 0.01 is the library's, for code that meshes without asking.)
    double maxPatchArea = 0.001;
    /// Stop when the method's residual (Solver.h) falls below this.
    double tolerance = 1e-4;
    std::size_t maxIterations = 100000;  ///< a solve that has not converged by then stops and says so
};

inline constexpr SolveDefaults kSolveDefaults{};

} // namespace radiant
