#pragma once
// The defaults every front end starts from - `radiant solve`, `probe`, `render` and `bench`, and
// the lab - stated once, here (the README's "Defaults" repeats them for readers).
#include <cstddef>

#include "radiometry/solver/Solver.h"

namespace radiant {

struct SolveDefaults {
    /// While the mesh is small (DefaultMethod.h: chooseDefaultMethod picks hierarchical beyond).
    /// Within 0.23% mean / 0.70% worst of the path tracer at the Cornell box's 18 points in 0.50 s,
    /// where Gauss-Seidel is 0.18% / 0.52% after 2.0 s of form factors (README, the accuracy table).
    SolverMethod method = SolverMethod::Progressive;
    /// m^2: 2,248 patches in the Cornell box (its floor cut along the blocks' footprints and meshed at
    /// half this area along their feet, MeshingOptions::besideContactAreaShare), where converged
    /// Gauss-Seidel is within 0.18% mean and 0.52% worst of the path tracer at the accuracy bench's 18
    /// points, and 0.96% worst on the box with its blocks square to the walls (2.5% at the earlier
    /// uniform 0.001 m^2, 2,805 patches); at 0.01 m^2 (260 patches, before the cut) 5.9% / 20% at 10
    /// points. The tables are in docs/ARCHITECTURE.md, "Defaults". MeshingOptions' own 0.01 is the
    /// library's, for code that meshes without asking.
    double maxPatchArea = 0.0013;
    /// Stop when the method's residual (Solver.h) falls below this.
    double tolerance = 1e-4;
    std::size_t maxIterations = 100000;  ///< a solve that has not converged by then stops and says so
};

inline constexpr SolveDefaults kSolveDefaults{};

} // namespace radiant
