#pragma once
// One interface for the five radiosity methods a course teaches. Each step() is one visible
// iteration, so a class can watch light spread and compare methods on the same scene.
//
//   B_i = E_i + rho_i * sum_j F_ij B_j      (per band; F_ij from patch i to patch j)
//
// with the scene's punctual lights as a source term: E_i + rho_i H_i, H_i their direct irradiance
// averaged over patch i (or element) with shadow rays (DirectLighting.h).
#include <cstdint>
#include <memory>
#include <span>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiometry/common/Progress.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/SolverMethods.h"
#include "radiometry/scene/View.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

class FormFactorMatrix;
class HierarchicalSolver;
class RayCaster;

/// The method's command-line name (the table in SolverMethods.h): "gauss-seidel".
std::string_view methodName(SolverMethod method);
/// Parses a method name; throws RadiantError naming the value and the accepted names.
SolverMethod parseMethod(std::string_view name);

struct IterationStats {
    std::size_t iteration = 0;      ///< 1 after the first step
    double residual = 1;            ///< max over bands of sum_i A_i |B_i - E_i - rho_i sum_j F_ij B_j| / sum_i A_i E_i
    PowerRgb unshotPower{};         ///< shooting methods: power not yet distributed (W); zero otherwise
    std::int64_t shooter = -1;      ///< progressive: the patch shot in this step
    std::size_t linksRefined = 0;   ///< hierarchical/importance: links created by refinement this step
    std::size_t links = 0;          ///< hierarchical/importance: links in total
    double seconds = 0;             ///< wall time of this step
};

struct SolverOptions {
    FormFactorOptions formFactors{};
    double matrixThreshold = 1e-7;     ///< gathering: form factors below this are dropped (mass reported)
    /// Hierarchical and importance: the link tolerance (`--link-tolerance`, the Solver panel's "Links"
    /// slider), unit-free. A link is refined while the radiosity error it may leave on its receiver,
    /// rho B dF A (W: reflectance, source radiosity, the form factor's spread over the receiver or its
    /// unresolved visibility, receiver area), exceeds this fraction of the scene's emitted power.
    /// Smaller is more accurate and slower: the error falls and the links grow about tenfold per 100x.
    double linkEpsilon = 1e-4;
    double minElementArea = 1e-5;      ///< hierarchical: m^2, elements are not split below this
    std::uint64_t seed = 1;
    /// Importance: the view whose image drives refinement; none: the scene's home view (View.h).
    std::optional<View> view;
    /// Gathering: refuse (BudgetError, before allocating) a form-factor matrix that may need more bytes.
    double matrixBudgetBytes = 4e9;
    /// The ray caster of the scene's geometry (RayCaster.h), shared by whoever holds it: the lab builds
    /// one per loaded scene. Null: the solver builds its own (the command line, the tests). A given one
    /// must have been built from a scene with the same surfaces and faces; materials do not matter.
    std::shared_ptr<const RayCaster> rays;
};

class Solver {
public:
    virtual ~Solver() = default;
    Solver() = default;
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    [[nodiscard]] virtual SolverMethod method() const = 0;
    /// Advances one iteration (a sweep, one shot, or a refine-and-gather round).
    virtual IterationStats step() = 0;
    /// Per-patch radiosity (W/m^2, per band), indexed like the mesh's patches.
    [[nodiscard]] virtual const std::vector<Rgb>& solution() const = 0;
    /// Changes a surface's material; keeps every form factor and link; the solve resumes from the
    /// current solution.
    virtual void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) = 0;
    /// Starts over from B = E, keeping form factors.
    virtual void reset() = 0;
    /// Statistics of the last step (iteration 0 before the first).
    [[nodiscard]] virtual const IterationStats& lastStats() const = 0;

    // Capabilities: what a method has beyond the solution, asked here instead of by casting.
    /// Bytes the solver holds (form factors, links, elements); 0 when it does not count them.
    [[nodiscard]] virtual std::size_t bytes() const { return 0; }
    /// The form-factor matrix the solver gathers over (Jacobi, Gauss-Seidel on the patches); null
    /// otherwise. Geometric only: another gathering solver of the same mesh may share it.
    [[nodiscard]] virtual std::shared_ptr<const FormFactorMatrix> formFactorMatrix() const { return nullptr; }
    /// The element hierarchy and its links, for methods that refine one; null otherwise.
    [[nodiscard]] virtual const HierarchicalSolver* hierarchy() const { return nullptr; }
    /// Per-patch importance (view-dependent methods); empty otherwise.
    [[nodiscard]] virtual std::span<const double> importance() const { return {}; }
    /// View-dependent methods refine for `view` from here on (scene: the one the solver was built
    /// from) and return true; others ignore it and return false. Throws RadiantError for a view that
    /// sees no surface's front, keeping the previous one.
    virtual bool setView(const Scene& /*scene*/, const View& /*view*/) { return false; }
};

/// Builds a solver for the meshed scene with the method's factory from the table. Expensive set-up (form-factor matrix, initial linking)
/// happens here, reporting to `progress` and honouring its cancellation.
std::unique_ptr<Solver> makeSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                   const SolverOptions& options = {}, Progress* progress = nullptr);

} // namespace radiant
