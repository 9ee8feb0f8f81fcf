#pragma once
// The closed furnace as a check of a mesh (the meshing tests): inside a closed surface of reflectance
// rho emitting 1 W/m^2 everywhere (the grey surfaces MeshTopology.h and the grouping files make),
// B = 1 / (1 - rho) on every patch and everything emitted is absorbed. A crack or an overlap left by
// the mesher lets light out or counts it twice. The form factors' row sums say how closed the mesh is
// numerically, and the tolerances follow from them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/Solver.h"
#include "tests/support/Relative.h"

namespace radiant::test {

/// Checks B = 1 / (1 - rho) on every patch by Gauss-Seidel without visibility rays (the inside of a
/// convex closed surface sees itself whole) and the energy balance; returns the furnace's exact B.
inline double checkClosedFurnace(const Scene& scene, const PatchMesh& mesh, double rho) {
    SolverOptions options;
    options.formFactors.visibilityRays = 0;
    const auto matrix = computeFormFactorMatrix(scene, mesh, options, nullptr);
    double deviation = 0;
    for (std::size_t i = 0; i < matrix->size(); ++i) deviation = std::max(deviation, std::abs(matrix->rowSum(i) - 1));
    MESSAGE(mesh.size() << " patches, row sums within " << deviation << " of 1");
    REQUIRE(deviation < 1e-2);
    const double expected = 1.0 / (1 - rho);
    // B = 1 + rho F B with row sums 1 + d at most: B within rho d / (1 - rho (1 + d)) of the exact.
    const double tolerance = rho * deviation / (1 - rho * (1 + deviation)) + 1e-5;
    auto solver = makeGaussSeidelSolver(scene, mesh, matrix);
    for (int k = 0; k < 1000 && solver->step().residual > 1e-9; ++k) {
    }
    double absorbed = 0, emitted = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        CHECK(solver->solution()[i].x == relativeTo(expected, tolerance));
        absorbed += (1 - rho) * mesh.patches[i].area * solver->solution()[i].x;
        emitted += mesh.patches[i].area * 1.0;
    }
    CHECK(absorbed == relativeTo(emitted, deviation + 1e-5));
    return expected;
}

} // namespace radiant::test
