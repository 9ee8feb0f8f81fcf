#pragma once
// Gathering over a precomputed form-factor matrix: each step() sweeps every patch once,
//   B_i <- E_i + rho_i sum_j F_ij B_j.
// Jacobi reads only the previous sweep's B; Gauss-Seidel reads the newest values as it goes.
//   M. F. Cohen, D. P. Greenberg, "The hemi-cube: a radiosity solution for complex environments",
//   SIGGRAPH 1985 (the matrix and its Gauss-Seidel solution);
//   M. F. Cohen, J. R. Wallace, "Radiosity and Realistic Image Synthesis", 1993, ch. 5.
#include <memory>
#include <vector>

#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/solver/SolverCommon.h"

namespace radiant {

class GatheringSolver : public Solver {
public:
    GatheringSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix);

    IterationStats step() final;
    [[nodiscard]] const std::vector<Rgb>& solution() const final { return radiosity_; }
    void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) final;
    void reset() final;
    [[nodiscard]] const IterationStats& lastStats() const final { return stats_; }

    [[nodiscard]] const FormFactorMatrix& matrix() const { return *matrix_; }
    [[nodiscard]] std::shared_ptr<const FormFactorMatrix> formFactorMatrix() const final { return matrix_; }
    /// Memory held: the matrix and the per-patch arrays.
    [[nodiscard]] std::size_t bytes() const override;

protected:
    /// One sweep over every patch; returns sum_i A_i |r_i| per band (W) for the new solution, with
    /// r_i = B_i - E_i - rho_i sum_j F_ij B_j.
    virtual Rgb sweep() = 0;
    /// Called when reset() replaces the solution, so caches of it can be dropped.
    virtual void solutionReplaced() {}
    /// The same sum for the current solution, by a full product with the matrix.
    Rgb residualPower();
    /// (sum_j F_ij B_j) for every i, in parallel over rows.
    void gatherAll(std::vector<Rgb>& gathered) const;

    PatchMaterials materials_;
    std::shared_ptr<const FormFactorMatrix> matrix_;
    std::vector<Rgb> radiosity_;  ///< W/m^2 per band

private:
    IterationStats stats_;
};

/// With an explicit matrix (analytic factors in tests, or one matrix shared by several solvers).
std::unique_ptr<Solver> makeJacobiSolver(const Scene& scene, const PatchMesh& mesh,
                                         std::shared_ptr<const FormFactorMatrix> matrix);
std::unique_ptr<Solver> makeGaussSeidelSolver(const Scene& scene, const PatchMesh& mesh,
                                              std::shared_ptr<const FormFactorMatrix> matrix);

/// With explicit per-unknown materials, matching the matrix's rows (the grouped system of
/// GroupedSolver.h, whose unknowns are groups of patches).
std::unique_ptr<Solver> makeJacobiSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix);
std::unique_ptr<Solver> makeGaussSeidelSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix);

/// The matrix makeJacobiSolver/makeGaussSeidelSolver compute: builds a RayCaster for the scene and
/// uses options.formFactors and options.matrixThreshold.
std::shared_ptr<const FormFactorMatrix> computeFormFactorMatrix(const Scene& scene, const PatchMesh& mesh,
                                                                const SolverOptions& options, Progress* progress);

} // namespace radiant
