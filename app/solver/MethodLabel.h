#pragma once
// Method names as people say them ("Gauss-Seidel"), for the window title and the Solver panel; the
// command line keeps radiometry's methodName() spelling ("gauss-seidel").
#include "radiometry/solver/Solver.h"

namespace radiant::app {

constexpr const char* methodLabel(SolverMethod method) {
    switch (method) {
    case SolverMethod::Jacobi: return "Jacobi";
    case SolverMethod::GaussSeidel: return "Gauss-Seidel";
    case SolverMethod::Progressive: return "Progressive refinement";
    case SolverMethod::Hierarchical: return "Hierarchical";
    case SolverMethod::Importance: return "Importance-driven";
    }
    return "?";
}

} // namespace radiant::app
