#pragma once
// Importance-driven radiosity: B. Smits, J. Arvo, D. Salesin, "An importance-driven radiosity
// algorithm", SIGGRAPH 1992.
//
// The camera emits importance: r_i, proportional to the share of the image element i fills
// (counted by casting a grid of rays through the image plane), per unit area. Importance obeys the
// adjoint of the radiosity equation,
//   A_i Y_i = A_i r_i + sum_j rho_j F_ji A_j Y_j,  i.e.  Y_i = r_i + sum_j F_ij rho_j Y_j,
// solved over the same links (reflectance applied at the source, not the receiver), so that
//   sum_i A_i r_i B_i = sum_i A_i E_i Y_i      (the image's mean radiosity, two ways).
// Refinement weighs each link's error by importance (and the importance error by radiosity): the
// surfaces the camera sees, directly or by one bounce, get the fine elements.
#include <vector>

#include "radiometry/solver/HierarchicalSolver.h"

namespace radiant {

class ImportanceSolver : public HierarchicalSolver {
public:
    /// Casts kImageResolution^2 eye rays through the image of options.view (the scene's home view
    /// when none). Throws RadiantError for a degenerate camera, and for a view that sees no
    /// surface's front: importance would be zero and nothing refined.
    ImportanceSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options, Progress* progress);
    /// Moves the camera (the lab's, when it stops): casts the eye rays again through the current
    /// elements and restarts importance from them; radiosity, elements and links stay, and the next
    /// steps refine for the new view. `scene` is the one the solver was built from. On a
    /// RadiantError (as the constructor's) the previous view stays in force.
    bool setView(const Scene& scene, const View& view) override;

    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Importance; }
    void reset() override;

    /// Per patch: importance Y (1/m^2), the direct share r plus what reaches the eye by reflection.
    [[nodiscard]] std::span<const double> importance() const override { return patchImportance_; }
    /// Per patch: emitted importance r (1/m^2), the share of eye rays landing on it per unit area.
    [[nodiscard]] const std::vector<double>& emittedImportance() const { return patchEmittedImportance_; }
    /// Per element importance Y (1/m^2), indexed like elements().
    [[nodiscard]] const std::vector<double>& elementImportance() const { return importance_; }
    /// Emitted importance r of an element (1/m^2).
    [[nodiscard]] double elementEmittedImportance(ElementIndex e) const;
    /// sum over leaves of A r B (W/m^2 per band): the mean radiosity of the image.
    [[nodiscard]] Rgb imageResponse() const;
    /// sum over leaves of A E Y (W/m^2 per band): the same quantity from the adjoint side.
    [[nodiscard]] Rgb adjointResponse() const;

    static constexpr int kImageResolution = 256;

protected:
    void onSubdivided(ElementIndex parent) override;
    void afterGather() override;
    void afterSolutionMapped() override;
    [[nodiscard]] double refinementThreshold() const override;

private:
    void castEyeRays(const Scene& scene, const View& view);
    void distributeHits(ElementIndex parent);
    void setImportanceToEmission();

    std::vector<glm::dvec3> hits_;  ///< front-face eye-ray hits, grouped by element
    std::vector<std::uint32_t> hitBegin_, hitEnd_;
    std::size_t rayCount_ = 0;
    double sceneArea_ = 0;
    std::vector<double> sourceImportance_, pushedImportance_;
    std::vector<std::vector<double>> gatherPerThread_;
    std::vector<double> patchImportance_, patchEmittedImportance_;
};

} // namespace radiant
