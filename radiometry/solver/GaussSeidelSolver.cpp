// Gauss-Seidel iteration on the radiosity system: patches are swept in order and each gathers the
// newest radiosities, so light found early in a sweep travels on within it; about half the
// sweeps of Jacobi for the same residual, but a sweep is sequential.
//   M. F. Cohen, D. P. Greenberg, "The hemi-cube: a radiosity solution for complex environments",
//   SIGGRAPH 1985; M. F. Cohen, J. R. Wallace, "Radiosity and Realistic Image Synthesis", 1993, sec. 5.3.
#include <algorithm>

#include <glm/common.hpp>

#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/ParallelFor.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

class GaussSeidelSolver final : public GatheringSolver {
public:
    using GatheringSolver::GatheringSolver;
    [[nodiscard]] SolverMethod method() const override { return SolverMethod::GaussSeidel; }

private:
    Rgb sweep() override {
        const std::size_t n = radiosity_.size();
        change_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            Rgb sum(0.0);
            for (const FormFactorEntry& e : matrix_->row(i)) sum += static_cast<double>(e.value) * radiosity_[e.column];
            const Rgb updated = materials_.source[i] + materials_.reflectance[i] * sum;
            change_[i] = updated - radiosity_[i];
            radiosity_[i] = updated;
        }
        // Row i held exactly when it was updated, with the old values for j > i; so its residual
        // now is rho_i sum_{j>i} F_ij (B_j new - B_j old): exact, at half a product's cost.
        std::vector<Rgb> rowResidual(n);
        parallelFor(n, 256, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const auto row = matrix_->row(i);
                const auto upper = std::partition_point(row.begin(), row.end(),
                                                        [i](const FormFactorEntry& e) { return e.column <= i; });
                Rgb sum(0.0);
                for (auto e = upper; e != row.end(); ++e) sum += static_cast<double>(e->value) * change_[e->column];
                rowResidual[i] = materials_.area[i] * glm::abs(materials_.reflectance[i] * sum);
            }
        });
        Rgb power(0.0);
        for (const Rgb& r : rowResidual) power += r;
        return power;
    }

    std::vector<Rgb> change_;  ///< B_i after minus before the current sweep
};

} // namespace

std::unique_ptr<Solver> makeGaussSeidelSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix) {
    return std::make_unique<GaussSeidelSolver>(std::move(materials), std::move(matrix));
}

std::unique_ptr<Solver> makeGaussSeidelSolver(const Scene& scene, const PatchMesh& mesh,
                                              std::shared_ptr<const FormFactorMatrix> matrix) {
    return std::make_unique<GaussSeidelSolver>(PatchMaterials::from(scene, mesh), std::move(matrix));
}

std::unique_ptr<Solver> makeGaussSeidelSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                              Progress* progress) {
    std::shared_ptr<const FormFactorMatrix> matrix = computeFormFactorMatrix(scene, mesh, options, progress);
    return std::make_unique<GaussSeidelSolver>(PatchMaterials::from(scene, mesh, options.rays.get()), std::move(matrix));
}

} // namespace radiant
