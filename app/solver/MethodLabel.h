#pragma once
// Method names as people say them ("Gauss-Seidel"), for the window title and the Solver panel; the
// command line keeps radiometry's methodName() spelling ("gauss-seidel"). Both come from the table.
#include "radiometry/solver/SolverMethods.h"

namespace radiant::app {

/// Null-terminated: the table's labels are string literals.
inline const char* methodLabel(SolverMethod method) { return methodInfo(method).label.data(); }

} // namespace radiant::app
