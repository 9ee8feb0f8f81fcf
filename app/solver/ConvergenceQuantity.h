#pragma once
// What a method's IterationStats::residual measures, named for the convergence plot's axis, its
// legend and the CSV: all three are fractions of the power the scene emits, so one tolerance and one
// log axis serve every method (SolverMethods.cpp has the definitions).
#include <string_view>

#include "radiometry/solver/SolverMethods.h"

namespace radiant::app {

struct ConvergenceQuantity {
    std::string_view name;     ///< on the axis and in the legend: "residual"
    std::string_view csvName;  ///< in the CSV's quantity column: "residual"
    std::string_view unit;     ///< "fraction of emitted power"
};

inline ConvergenceQuantity convergenceQuantity(SolverMethod method) {
    constexpr std::string_view kUnit = "fraction of emitted power";
    const SolverTraits traits = methodInfo(method).traits;
    if (traits.shoots) return {"unshot power", "unshot_power_fraction", kUnit};
    if (traits.links) return {"sweep change", "sweep_change_fraction", kUnit};
    return {"residual", "residual_fraction", kUnit};
}

} // namespace radiant::app
