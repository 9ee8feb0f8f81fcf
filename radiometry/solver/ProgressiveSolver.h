#pragma once
// Progressive refinement radiosity: each step shoots the unshot radiosity of the patch with the
// most unshot power to every other patch, with form factors computed for that shot only - no
// matrix, so memory grows with the patch count, not its square.
//   M. F. Cohen, S. E. Chen, J. R. Wallace, D. P. Greenberg, "A progressive refinement approach to
//   fast radiosity image generation", SIGGRAPH 1988 (shooting, shooter order, the ambient term);
//   S. E. Chen, "Incremental radiosity: an extension of progressive radiosity to an interactive
//   image synthesis system", SIGGRAPH 1990 (material edits shot as positive or negative light).
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "radiometry/solver/Solver.h"
#include "radiometry/solver/SolverCommon.h"

namespace radiant {

/// Fills toShooter[j] = F_{j -> shooter} (dimensionless) for every patch j; 0 for the shooter
/// itself and for patches that cannot see it. Called from one thread at a time.
using ShotFormFactors = std::function<void(std::size_t shooter, std::span<double> toShooter)>;

class ProgressiveSolver final : public Solver {
public:
    ProgressiveSolver(PatchMaterials materials, ShotFormFactors formFactors);

    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Progressive; }
    /// Shoots once. Residual = sum_i A_i |unshot B_i| / sum_i A_i E_i (max over bands): an upper
    /// bound of the gathering residual sum_i A_i |rho_i sum_j F_ij unshot B_j| / sum_i A_i E_i,
    /// since rho < 1 and sum_i A_i F_ij <= A_j.
    IterationStats step() override;
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return radiosity_; }
    void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) override;
    void reset() override;
    [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }

    /// Cohen et al.'s ambient term, W/m^2 per band: the unshot power spread evenly over the area and
    /// reflected by the area-mean reflectance 1/(1 - rho_mean) times. For display only.
    [[nodiscard]] Rgb ambient() const;
    /// B_i + rho_i ambient: an early image close to the converged one in overall brightness.
    [[nodiscard]] std::vector<Rgb> solutionWithAmbient() const;
    /// Radiosity received but not yet shot, W/m^2 per band (negative after a material got darker).
    [[nodiscard]] const std::vector<Rgb>& unshot() const { return unshot_; }
    /// Memory held by the per-patch arrays (not the shot kernel's geometry and ray caster).
    [[nodiscard]] std::size_t bytes() const {
        return materials_.size() * (sizeof(double) * 2 + sizeof(Rgb) * 5);
    }

private:
    /// Refreshes the shooter choice and the residual from unshot_ (after reset or an edit).
    void rescan();

    PatchMaterials materials_;
    ShotFormFactors formFactors_;
    std::vector<Rgb> radiosity_;   ///< B = E + rho H, W/m^2
    std::vector<Rgb> unshot_;      ///< W/m^2
    std::vector<Rgb> irradiance_;  ///< H: everything gathered so far, W/m^2; survives material edits
    std::vector<double> toShooter_;
    std::size_t nextShooter_ = 0;
    double nextShooterPower_ = 0;  ///< A |unshot B| summed over bands, W
    IterationStats stats_;
};

std::unique_ptr<ProgressiveSolver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh,
                                                         ShotFormFactors formFactors);

/// The form factors of a shot from the real geometry: cull by planes, the exact point-to-polygon
/// kernel at the receiver's centroid where the receiver is small for its distance, the area
/// quadrature with reciprocity where it is not, times the ray-cast visibility fraction. Parallel
/// over receivers; owns its ray caster.
ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options);

} // namespace radiant
