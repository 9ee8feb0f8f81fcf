#include "radiometry/solver/GatheringSolver.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include <glm/common.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "radiometry/solver/ParallelFor.h"

namespace radiant {

GatheringSolver::GatheringSolver(PatchMaterials materials, std::shared_ptr<const FormFactorMatrix> matrix)
    : materials_(std::move(materials)), matrix_(std::move(matrix)) {
    if (!matrix_ || matrix_->size() != materials_.size())
        throw RadiantError({"", "form-factor matrix"},
                           "has " + std::to_string(matrix_ ? matrix_->size() : 0) + " rows for " +
                               std::to_string(materials_.size()) + " patches");
    reset();
}

void GatheringSolver::reset() {
    radiosity_ = materials_.source;
    solutionReplaced();
    stats_ = {};
    stats_.residual = fractionOfEmitted(residualPower(), materials_.emittedPower());
}

void GatheringSolver::setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) {
    materials_.setSurface(surface, reflectance, exitance);
    stats_.residual = fractionOfEmitted(residualPower(), materials_.emittedPower());
}

IterationStats GatheringSolver::step() {
    const auto start = std::chrono::steady_clock::now();
    const Rgb power = sweep();
    stats_.iteration += 1;
    stats_.residual = fractionOfEmitted(power, materials_.emittedPower());
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats_;
}

void GatheringSolver::gatherAll(std::vector<Rgb>& gathered) const {
    gathered.resize(radiosity_.size());
    parallelFor(radiosity_.size(), 256, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            Rgb sum(0.0);
            for (const FormFactorEntry& e : matrix_->row(i)) sum += static_cast<double>(e.value) * radiosity_[e.column];
            gathered[i] = sum;
        }
    });
}

std::size_t GatheringSolver::bytes() const {
    // area, reflectance, exitance, the lights' H, the source E + rho H, B, and one more Rgb per patch
    // for the sweep's scratch array.
    return matrix_->bytes() + materials_.size() * (sizeof(double) + 6 * sizeof(Rgb));
}

Rgb GatheringSolver::residualPower() {
    std::vector<Rgb> gathered;
    gatherAll(gathered);
    Rgb power(0.0);
    for (std::size_t i = 0; i < radiosity_.size(); ++i)
        power += materials_.area[i] *
                 glm::abs(radiosity_[i] - materials_.source[i] - materials_.reflectance[i] * gathered[i]);
    return power;
}

std::shared_ptr<const FormFactorMatrix> computeFormFactorMatrix(const Scene& scene, const PatchMesh& mesh,
                                                                const SolverOptions& options, Progress* progress) {
    checkFormFactorMatrixBudget(mesh.size(), options.matrixBudgetBytes);  // before any allocation
    std::optional<RayCaster> own;  // only when the caller shares none (SolverOptions::rays)
    const RayCaster* rays = options.rays ? options.rays.get() : &own.emplace(scene);
    FormFactorOptions formFactors = options.formFactors;
    formFactors.seed = pairSeed(options.seed, options.formFactors.seed, 0);
    return std::make_shared<const FormFactorMatrix>(
        FormFactorMatrix::compute(mesh, rays, formFactors, options.matrixThreshold, progress));
}

} // namespace radiant
