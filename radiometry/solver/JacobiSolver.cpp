// Jacobi iteration on the radiosity system: every patch gathers from the previous sweep's
// radiosities, so a sweep is one matrix-vector product, parallel over rows, and its k-th iterate
// from B = E is the k-bounce truncation of the Neumann series sum_m (rho F)^m E.
//   M. F. Cohen, J. R. Wallace, "Radiosity and Realistic Image Synthesis", 1993, sec. 5.3.
#include <glm/common.hpp>

#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

class JacobiSolver final : public GatheringSolver {
public:
    using GatheringSolver::GatheringSolver;
    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Jacobi; }

private:
    Rgb sweep() override {
        // gathered_ = F B for the current B, so B' = E + rho gathered_; then F B' gives the new
        // solution's exact residual and the next sweep's gather: one product per sweep.
        if (gathered_.size() != radiosity_.size()) gatherAll(gathered_);
        for (std::size_t i = 0; i < radiosity_.size(); ++i)
            radiosity_[i] = materials_.source[i] + materials_.reflectance[i] * gathered_[i];
        gatherAll(gathered_);
        Rgb power(0.0);
        for (std::size_t i = 0; i < radiosity_.size(); ++i)
            power += materials_.area[i] *
                     glm::abs(radiosity_[i] - materials_.source[i] - materials_.reflectance[i] * gathered_[i]);
        return power;
    }

    void solutionReplaced() override { gathered_.clear(); }

    std::vector<Rgb> gathered_;  ///< sum_j F_ij B_j for the current B; empty when unknown
};

} // namespace

std::unique_ptr<Solver> makeJacobiSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix) {
    return std::make_unique<JacobiSolver>(std::move(materials), std::move(matrix));
}

std::unique_ptr<Solver> makeJacobiSolver(const Scene& scene, const PatchMesh& mesh,
                                         std::shared_ptr<const FormFactorMatrix> matrix) {
    return std::make_unique<JacobiSolver>(PatchMaterials::from(scene, mesh), std::move(matrix));
}

std::unique_ptr<Solver> makeJacobiSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                         Progress* progress) {
    std::shared_ptr<const FormFactorMatrix> matrix = computeFormFactorMatrix(scene, mesh, options, progress);
    return std::make_unique<JacobiSolver>(PatchMaterials::from(scene, mesh, options.rays.get()), std::move(matrix));
}

} // namespace radiant
