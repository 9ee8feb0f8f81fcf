#pragma once
// Where one solve stands, as the comparison's labels and the Probe panel's comparison rows say it.
// A snapshot's radiosity before the first step is only the initial guess (the emission, or zero
// while form factors compute): nothing a comparison may set against another solution.
#include <optional>
#include <string>

#include "app/solver/Snapshot.h"

namespace radiant::app {

/// The snapshot holds a solution: a mesh, a radiosity per patch, and at least one step taken.
[[nodiscard]] bool hasStepped(const Snapshot& s);

/// One line: "meshing", "computing form factors 45%", "ready (Space runs both)", or "iteration 12,
/// unshot power 3.1e-04, converged" (each method's own measure by name), or the last error.
/// `longWorkDone`: the share of the meshing or form factors done (longWorkDone(thread)), if known.
[[nodiscard]] std::string progressLine(const Snapshot& s, std::optional<double> longWorkDone = std::nullopt);

class SolverThread;
/// The share of `thread`'s meshing or form-factor work done, while it does such work.
[[nodiscard]] std::optional<double> longWorkDone(const SolverThread& thread);

} // namespace radiant::app
