#include "app/solver/SolveProgress.h"

#include <cstdio>

#include "app/solver/ConvergenceQuantity.h"
#include "app/solver/SolverThread.h"

namespace radiant::app {

bool hasStepped(const Snapshot& s) {
    return s.scene && s.mesh && !s.radiosity.empty() && s.radiosity.size() == s.mesh->size() && !s.history.empty();
}

std::string progressLine(const Snapshot& s, std::optional<double> longWorkDone) {
    if (!s.error.empty()) return s.error;
    char text[96];
    const char* work = !s.mesh ? "meshing" : s.solverBuilds == 0 ? "computing form factors" : nullptr;
    if (work) {
        if (!longWorkDone) return work;
        std::snprintf(text, sizeof text, "%s %.0f%%", work, 100 * *longWorkDone);
        return text;
    }
    if (s.stats.iteration == 0) return s.running ? "starting" : "ready (Space runs both)";
    const bool converged = !s.running && s.stats.residual < s.tolerance;
    // Each method's own measure by name, as the status line and the plot's axis say it.
    std::snprintf(text, sizeof text, "iteration %zu, %s %.1e%s", s.stats.iteration,
                  std::string(convergenceQuantity(s.method).name).c_str(), s.stats.residual,
                  converged ? ", converged" : "");
    return text;
}

std::optional<double> longWorkDone(const SolverThread& thread) {
    const SolverActivity activity = thread.activity();
    if (activity != SolverActivity::Meshing && activity != SolverActivity::FormFactors) return std::nullopt;
    return thread.progress().fraction();
}

} // namespace radiant::app
