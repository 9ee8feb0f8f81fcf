#pragma once
// Progressive refinement radiosity: each step shoots the unshot radiosity of the patch with the
// most unshot power to every other patch, with form factors computed for that shot only - no
// matrix, so memory grows with the patch count, not its square.
//   M. F. Cohen, S. E. Chen, J. R. Wallace, D. P. Greenberg, "A progressive refinement approach to
//   fast radiosity image generation", SIGGRAPH 1988 (shooting, shooter order, the ambient term);
//   S. E. Chen, "Incremental radiosity: an extension of progressive radiosity to an interactive
//   image synthesis system", SIGGRAPH 1990 (material edits shot as positive or negative light);
//   M. F. Cohen, D. P. Greenberg, D. S. Immel, P. J. Brock, "An efficient radiosity approach for
//   realistic image synthesis", IEEE CG&A 1986 (coarse shooters, fine receivers: see
//   ProgressiveShooters.h).
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "radiometry/solver/ProgressiveShooters.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/solver/SolverCommon.h"

namespace radiant {

/// Fills toShooter[j] = F_{j -> shooter} (dimensionless) for every patch j; 0 for the shooter
/// itself and for patches that cannot see it. Called from one thread at a time. `shooter` is a
/// patch index, or with ProgressiveShooters a group index and F_{j -> group} to the whole group.
/// `shot` counts the shooter's earlier shots since the solve began (ProgressiveSolver::reset): with
/// the shooter it seeds the shot's visibility rays, so a shooter shooting again draws fresh rays and
/// a solve started over draws the same ones. A count kept inside the form factors outlived reset,
/// and the lab's solve after Reset differed from its first (up to 25% on a penumbra patch).
using ShotFormFactors = std::function<void(std::size_t shooter, std::uint32_t shot, std::span<double> toShooter)>;
/// ShotFormFactors for a group, told where in it the light leaves from: memberPower[k] >= 0 per band
/// is the share of the shot's unshot power held by the group's k-th patch in that band (all of them,
/// over members and bands, sum to 1), so visibility can be sampled where the light is, not over parts
/// of the group that hold none (floor under a box), and each band leaves from where that band's
/// light is. toShooter[j] is F_{j -> group} per band, each band's power weighing the members.
/// powerShare is the shot's unshot power as a fraction of the emitted power (band sums): a shot that
/// carries much of the light (the light source's own) gets more visibility rays in penumbrae, since
/// its noise is not averaged away by later shots.
using GroupShotFormFactors = std::function<void(std::size_t group, std::uint32_t shot, std::span<const Rgb> memberPower,
                                                double powerShare, std::span<Rgb> toShooter)>;

class ProgressiveSolver final : public Solver {
public:
    ProgressiveSolver(PatchMaterials materials, ShotFormFactors formFactors);
    /// Groups of patches shoot together: a group's unshot power sum_i A_i dB_i leaves it in one shot,
    /// formFactors weighing each member by its share of it; each patch still receives on its own.
    /// formFactors takes group indices.
    ProgressiveSolver(PatchMaterials materials, ProgressiveShooters shooters, GroupShotFormFactors formFactors);

    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Progressive; }
    /// Shoots once (one group). IterationStats::shooter is the group's patch with the most unshot
    /// power. Residual = sum_i A_i |unshot B_i| / sum_i A_i E_i (max over bands): an upper
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
    [[nodiscard]] const ProgressiveShooters& shooters() const { return shooters_; }
    /// The group shot by the last step, or -1.
    [[nodiscard]] std::int64_t lastShooterGroup() const { return lastGroup_; }
    /// Memory held by the per-patch and per-group arrays (not the shot kernel's ray caster).
    [[nodiscard]] std::size_t bytes() const override {
        return materials_.size() * (sizeof(double) * 2 + sizeof(Rgb) * 5 + sizeof(std::uint32_t)) +
               shooters_.size() * (sizeof(std::uint32_t) * 4 + sizeof(PatchPolygon) + sizeof(double));
    }

private:
    /// Checks the groups against the materials, sums their areas, and resets.
    void prepareShooters();
    /// Refreshes the shooter choice and the residual from unshot_ (after reset or an edit).
    void rescan();

    PatchMaterials materials_;
    ProgressiveShooters shooters_;
    GroupShotFormFactors formFactors_;
    std::vector<Rgb> memberPower_;
    std::vector<double> shooterArea_;  ///< m^2 per group
    std::vector<Rgb> radiosity_;   ///< B = E + rho H, W/m^2
    std::vector<Rgb> unshot_;      ///< W/m^2
    std::vector<Rgb> irradiance_;  ///< H: everything gathered so far, W/m^2; survives material edits
    std::vector<Rgb> toShooter_;
    std::vector<std::uint32_t> timesShot_;  ///< per group, since reset: ShotFormFactors' `shot`
    std::size_t nextShooter_ = 0;  ///< a group
    double nextShooterPower_ = 0;  ///< sum over its patches of A |unshot B| summed over bands, W
    std::int64_t lastGroup_ = -1;
    IterationStats stats_;
};

std::unique_ptr<ProgressiveSolver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh,
                                                         ShotFormFactors formFactors);

struct ProgressiveOptions {
    /// Sets the block size: each face's grid is cut into blocks of about sqrt(patches / shooterCount)
    /// cells a side (1 below that many patches), so there are about shooterCount full blocks plus
    /// smaller ones at grid edges and on small faces (the Cornell box at 10k patches: 78 shooters,
    /// residual 1e-2 after 208 shots; 400 gives 464 shooters and is still at 0.06 after 640 shots).
    /// Larger blocks take fewer shots; each member still sends its own share of a shot's power
    /// (ProgressiveShot.cpp), so on the Cornell box at 577 patches blocks of 2-4 cells converge to
    /// Gauss-Seidel within 0.4-1.9% per surface and 0.9-1.4% per patch on average.
    std::size_t shooterCount = 50;
    std::size_t shooterBlock = 0;  ///< when > 0, this block size instead
};

/// Block shooters over the real geometry: what makeSolver(Progressive, ...) builds.
std::unique_ptr<ProgressiveSolver> makeProgressiveSolver(const Scene& scene, const PatchMesh& mesh,
                                                         const SolverOptions& options,
                                                         const ProgressiveOptions& progressive);

/// The form factors of a shot from the real geometry: cull by planes, the exact point-to-polygon
/// kernel at the receiver's centroid where the receiver is small for its distance, the area
/// quadrature with reciprocity where it is not, times the ray-cast visibility fraction. Parallel
/// over receivers; owns its ray caster.
ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options);
/// The same to groups of patches (shooters.polygons must be set): F_{j -> group} for every patch j.
/// The receiver's points and rays are chosen by its distance to the group's outline, not to its
/// centre, so receivers beside a large group are still integrated finely.
ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                           const ProgressiveShooters& shooters, const SolverOptions& options);
/// The same, with each shot's visibility rays aimed at points of the group's patches drawn in
/// proportion to their share of the unshot power (stratified over that share); the unoccluded
/// kernel stays the exact one to the group's outline. Without a share (the overload above, or all
/// zero), in proportion to area.
GroupShotFormFactors makeRayCastGroupShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                                     const ProgressiveShooters& shooters, const SolverOptions& options);

} // namespace radiant
