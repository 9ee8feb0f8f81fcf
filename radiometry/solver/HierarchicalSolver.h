#pragma once
// Hierarchical radiosity: P. Hanrahan, D. Salzman, L. Aupperle, "A rapid hierarchical radiosity
// algorithm", SIGGRAPH 1991.
//
// Every face is the root of a quadtree of elements. Links join pairs of elements; a link is
// refined (its larger element split, the link replaced by four finer ones) while its "BF" error
// estimate rho_p B_q dF_pq A_p exceeds linkEpsilon times the emitted power, until elements reach
// minElementArea. dF is the form factor's uncertainty: the spread of the exact point-to-polygon
// kernel over the receiver (the error of giving the whole receiver one value; near contact its
// corners count too), or the whole form factor when a few rays find the link partially visible, so
// shadow boundaries refine further than fully visible or fully hidden links (a link whose rays were
// all blocked draws more where it would refine were it partial). Refinement stops when a step makes
// no links or changes B by under kSettleResidual; the gather rows are then built. Where the source is small
// against its distance the kernel is a 2 x 2 Gauss rule over it (HierarchicalFormFactor.h). Every
// link casts its own visibility rays (an unbiased estimate). To scale by element count, leaves
// are split down to a target area and the threshold is tied to it (hierarchicalSetupForElements).
// One step() = refine where needed, gather H_p = sum F_pq B_q over each element's links (both
// cores), then push-pull: irradiance pushed down to the leaves (B = E + rho H there), each link's
// with its variation over its receiver (the kernel at the receiver's children, bilinear below them:
// ReceiverShape.h), radiosity pulled up as the area-weighted mean of the children. The scene's punctual lights are a source
// term per element: B = E + rho (H_e + gathered), H_e their direct irradiance averaged over the
// element with shadow rays, computed as elements appear (HierarchicalDirectLight.cpp). What a patch and a probe point show is gathered
// at their points over the same links (HierarchicalGather.cpp), not the leaf's constant.
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/solver/HierarchicalLink.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/sources/DirectLighting.h"

namespace radiant {

namespace hierarchical {
struct SourceRule;
}

/// Element resolution asked of the hierarchy on top of the refinement oracle.
struct HierarchicalRefinement {
    /// 0: none (elements exist only where the oracle split them). > 0 (m^2): every leaf larger than
    /// this is split before linking, so the solution has at least this resolution everywhere. Where
    /// no link needs them, the leaves take their irradiance from their ancestors' links (push-pull);
    /// hierarchicalSetupForElements tightens the threshold with the leaf size so that fewer do.
    double maxLeafArea = 0;
};

class HierarchicalSolver : public Solver {
public:
    /// Builds the element tree (one root per face, split down to refinement.maxLeafArea), the ray caster when visibility is asked for
    /// (options.formFactors.visibilityRays > 0) and the initial links between every pair of roots
    /// that face each other.
    HierarchicalSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options, Progress* progress,
                       HierarchicalRefinement refinement = {});
    ~HierarchicalSolver() override;

    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Hierarchical; }
    IterationStats step() override;
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return solution_; }
    void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) override;
    void reset() override;
    [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }

    /// The elements (the window draws the leaves) and the links between them.
    [[nodiscard]] const ElementTree& elements() const { return tree_; }
    [[nodiscard]] std::span<const Link> links() const { return links_; }
    /// For each mesh patch, the element whose radiosity it shows (about the patch's size or the
    /// deepest one under its centroid).
    [[nodiscard]] std::span<const ElementIndex> patchElements() const { return patchElement_; }
    /// Radiosity at `point` on face `face` of surface `surface` (W/m^2 per band): E + rho H(x), H
    /// gathered at x over the links of every element containing x with the exact point kernel and a
    /// visibility of x's own (kPointVisibilityRaysPerSide^2 rays per link). What the
    /// probe reads: the leaf's constant is off by the kernel's variation across the leaf. Zero for a
    /// face that does not exist. Thread-safe against other const calls, not against step().
    [[nodiscard]] Rgb radiosityAt(std::uint32_t surface, std::uint32_t face, const glm::dvec3& point) const;
    static constexpr int kPointVisibilityRaysPerSide = 8;
    /// Above this many leaves the leaf rows' memory (about 8 bytes per link of a leaf's chain, ~60 per
    /// leaf) is not spent and push-pull pushes the ancestors' irradiance down as constants.
    static constexpr std::size_t kMaxLeavesWithRows = 1u << 18;
    /// Heap bytes held by elements, links and the solver's per-element arrays.
    [[nodiscard]] std::size_t bytes() const override;
    [[nodiscard]] const HierarchicalSolver* hierarchy() const override { return this; }
    /// Visibility rays cast by refinement so far.
    [[nodiscard]] std::size_t raysCast() const;

    /// Visibility rays per new link and per set (stratified; two independent sets, see makeLink): few,
    /// because the oracle only needs to know whether a link is fully visible, fully hidden or partial,
    /// and a partial link refines until its share matters little.
    static constexpr int kLinkVisibilityRays = 4;
    /// How much a link that every ray found blocked counts in the oracle, relative to a visible one.
    static constexpr double kHiddenErrorWeight = 0.25;
    /// Rays that confirm a link every oracle ray found blocked, where the link would refine were it
    /// partially visible (makeLink).
    static constexpr int kHiddenCheckRays = 16;
    /// Refinement stops, and the gather rows are built, once a step that refined changes B by less
    /// than this (its residual) even if the oracle still asks for a few links (not after the
    /// importance view changed: resumeRefinement).
    static constexpr double kSettleResidual = 1e-3;

protected:
    /// Called after `parent` was split (serially, between parallel phases).
    virtual void onSubdivided(ElementIndex /*parent*/) {}
    /// Called after the radiosity gather and push-pull of a step, before the solution is mapped.
    virtual void afterGather() {}
    /// Called after the per-patch solution was refreshed.
    virtual void afterSolutionMapped() {}
    /// Lets refinement resume after the leaf rows stopped it (the importance changed with the view).
    void resumeRefinement() {
        linksSettled_ = false;
        refinedSinceChange_ = false;
        settleOnResidual_ = false;
    }
    /// A link is refined while its error estimate exceeds this (W for plain hierarchical radiosity).
    [[nodiscard]] virtual double refinementThreshold() const;

    /// Per-element importance (1/m^2), empty for plain hierarchical radiosity; when present the
    /// oracle weighs each link's error by it (importance-driven refinement, Smits et al. 1992).
    std::vector<double> importance_;

    [[nodiscard]] unsigned threads() const { return threads_; }
    /// The scene's ray caster: the shared one given (SolverOptions::rays), else the one built for
    /// visibility or the lights; null when none was given and neither needs one.
    [[nodiscard]] const RayCaster* rayCaster() const { return sceneRays_.get(); }
    [[nodiscard]] std::span<const Rgb> surfaceReflectance() const { return surfaceReflectance_; }
    /// Sum over the roots of A (E + rho H), the larger band (W): the scale of the refinement threshold.
    [[nodiscard]] double emittedPower() const;
    /// Mean reflectance over the bands of the element's surface.
    [[nodiscard]] double meanReflectance(ElementIndex e) const;
    /// The element's source term E + rho H (W/m^2 per band): emission and the lights' reflected
    /// direct light. Valid for elements lit by lightNewElements().
    [[nodiscard]] Rgb elementSource(ElementIndex e) const;

private:
    struct Split {
        std::size_t link;
        bool splitReceiver;
    };

    void splitLeavesLargerThan(double area);
    void linkRoots(Progress* progress);
    /// Appends the link receiver <- source to `out` when the two can exchange light. Returns the
    /// number of visibility rays cast.
    struct NewLink {
        Link link;
        float share = 0;  ///< its visible share (the link's formFactor is F times it)
        std::array<float, 4> shape{};  ///< see linkShape_
    };
    std::size_t makeLink(ElementIndex receiver, ElementIndex source, std::vector<NewLink>& out) const;
    [[nodiscard]] double linkError(const Link& link) const;
    [[nodiscard]] bool canSplit(ElementIndex e) const;
    std::size_t refine();
    void gather();
    /// Returns the residual of the radiosity the gather started from.
    double pushPull();
    /// Refreshes the per-patch solution: `gathered` (refinement has settled), each patch's mean of the
    /// links' gather (by its patch row, kept while the links stay); otherwise (while refining, before
    /// the first step, after reset) the elements' own values.
    void mapSolution(bool gathered);
    struct GatherTerm {
        ElementIndex source;
        float weight;  ///< F(x -> source) times its visible share, averaged over the patch's points
    };
    /// Links grouped by receiver (HierarchicalGather.cpp).
    void indexLinksByReceiver();
    /// Calls expand(link) for every link of `leaf` and its ancestors (`everyLink`: also those whose
    /// rays found them hidden) that may light x: expand appends the link's terms, kernel(q) x
    /// visibility, q the link's source or, where that is large for its distance from `x`, its
    /// descendants (expandSource, expandSourceScaled). `faces(q)`: whether the receiving point or
    /// patch may see any of q's front (a cheap test before the kernel).
    template <class Faces, class Expand>
    void gatherTerms(ElementIndex leaf, const glm::dvec3& x, Faces&& faces, Expand&& expand, bool everyLink) const;
    /// Appends kernel(source) x visibility(link, source, its polygon), or the same for the source's
    /// children where it is large for its distance from x (area over squared distance above
    /// kSourceExpansion).
    template <class Kernel, class Visibility>
    void expandSource(std::uint32_t link, ElementIndex source, const glm::dvec3& x, Kernel& kernel, Visibility& visibility,
                      std::vector<GatherTerm>& out) const;
    static constexpr double kSourceExpansion = 0.05;
    /// expandSource for a patch's row, with the same terms: those within sqrt(farDistance2) of x take
    /// kernel(term) (the kernel averaged over the patch's points); the farther ones share what
    /// kernel(the link's whole source) leaves after the nearer terms, in proportion to estimate(term)
    /// (the kernel at one point): exact in sum, one point per far term instead of four.
    template <class Kernel, class Estimate, class Visibility>
    void expandSourceScaled(std::uint32_t link, const glm::dvec3& x, double farDistance2, Kernel& kernel, Estimate& estimate,
                            Visibility& visibility, std::vector<ElementIndex>& terms, std::vector<double>& values,
                            std::vector<GatherTerm>& out) const;
    /// sourceRules_ for every element (kept from the leaf rows to the patch rows of the same step).
    void buildSourceRules();
    /// sourceRules_ for the elements made since the last call, for refinement's link kernels
    /// (hierarchical::linkKernel); none above kMaxElementsWithLinkRules elements (~1.2 KB each), where
    /// links take Lambert's integral as before.
    void extendSourceRules();
    static constexpr std::size_t kMaxElementsWithLinkRules = 1u << 15;
    /// Each patch's gather row, rebuilt when refinement changed the links.
    void buildPatchRows();
    /// What each leaf gathers once refinement has settled, in place of its ancestors' means pushed
    /// down: a leaf the patches resolve (their Gauss points inside it, kPatchOverLeaf) reads the
    /// patch rows at those points (leafPoints_); any other leaf gets a gather row of its own, every
    /// link of the leaf and its ancestors with the form factor from the leaf itself. Builds the patch
    /// rows too (after the own rows, which share their source rules). Rebuilt when refinement changed
    /// the links.
    void buildLeafRows();
    /// leafIrradiance_ from the patch and leaf rows and the current radiosity (both cores).
    void gatherLeafRows();
    /// A leaf reads the patch rows at those of the patches' 3 x 3 Gauss points it holds whose patch is
    /// no larger than this times the leaf (on the Cornell box all but 100-136 of hierarchical's ~1,730
    /// leaves, all but ~1,070 of importance's ~3,180). The fewer own rows the better there (leaves
    /// reading the patches only where they hold 4 of those points, 1,333 of importance's 3,164 kept
    /// rows, where 9 left 2,074, and the patches' distance from converged Gauss-Seidel grew with
    /// them), but a leaf much smaller than its patch takes a blur (buildLeafRows says how much).
    static constexpr double kPatchOverLeaf = 4;

    /// Whether no face of the scene can block a segment between the link's receiver and source
    /// (hierarchical::Shaft against every occluder): then every part of the receiver sees all of every
    /// part of the source. Tested once per link, when first asked, while the patch rows are built.
    /// False without occluders to test.
    [[nodiscard]] bool shaftClear(std::uint32_t link) const;
    /// Whether no occluder's bounding box meets the bounding box of a and b (then no face can block a
    /// segment between them: their visibility is 1 without rays). False without occluders to test.
    [[nodiscard]] bool occludersMissBoxOf(const PatchPolygon& a, const PatchPolygon& b) const;

    /// The irradiance a patch's row gathers from the tree's radiosity.
    [[nodiscard]] Rgb patchRowIrradiance(std::size_t patch) const;
    /// E + rho (its row's irradiance, patchIrradiance_, + the lights' direct part) for a patch whose
    /// row is built.
    [[nodiscard]] Rgb gatheredRadiosity(std::size_t patch) const;
    void setLeavesToEmission();
    /// H for the elements created since the last call (and each patch's on the first), in parallel.
    void lightNewElements();
    /// rho (H of the patch - H of the element it shows): the lights' direct part at the patch's
    /// resolution where the patch shows an element's constant; zero without lights.
    [[nodiscard]] Rgb patchDirectCorrection(std::size_t patch) const;

    SolverOptions options_;
    HierarchicalRefinement refinement_;
    ElementTree tree_;
    std::shared_ptr<const RayCaster> caster_;  ///< sceneRays_ when links test visibility, else null
    int visibilityRays_ = 0;
    /// The oracle's threshold when the links being made were asked for (makeLink's hidden check).
    double hiddenCheckThreshold_ = std::numeric_limits<double>::infinity();
    std::vector<Link> links_;
    std::vector<float> linkShare_;  ///< per link, its visible share (for the gather at points)
    /// Per link, its form factor over each of the receiver's four children-to-be (their mean is the
    /// link's formFactor): push-pull hands each child its own (ReceiverShape.h).
    std::vector<std::array<float, 4>> linkShape_;
    std::vector<Rgb> gatheredShape_;  ///< per element, 4 irradiances (gather(), then pushed in place)
    std::vector<Rgb> surfaceReflectance_;
    std::vector<Rgb> surfaceExitance_;
    std::shared_ptr<const RayCaster> sceneRays_;  ///< see rayCaster()
    std::unique_ptr<DirectLighting> lighting_;  ///< null without lights
    std::vector<Rgb> elementDirect_;  ///< H per element, W/m^2 (empty without lights)
    std::vector<Rgb> patchDirect_;    ///< H per patch, for the gathered per-patch solution

    struct PatchSample {
        std::uint32_t surface, face;
        glm::dvec3 centroid;
        double area;
        PatchPolygon polygon;
        bool covered = false;  ///< Patch::covered: under a block, seeing only backs
    };
    std::vector<PatchSample> patches_;
    std::vector<ElementIndex> patchElement_;
    std::size_t mappedTreeSize_ = 0;
    std::vector<Rgb> solution_;
    std::vector<std::uint32_t> receiverLinkBegin_, receiverLinks_;
    /// The scene's faces that may block (RayCaster::mayBlock), the occluders shaftClear tests: corners
    /// of occluder k are occluderCorners_[occluderBegin_[k] .. occluderBegin_[k + 1]), its bounding box
    /// occluderBox_[2 k .. 2 k + 1]. Empty above kMaxShaftOccluders faces, where testing every face per
    /// link would cost more than its rays.
    std::vector<glm::dvec3> occluderCorners_;
    std::vector<std::uint32_t> occluderBegin_;
    std::vector<glm::dvec3> occluderBox_;
    double shaftTolerance_ = 0;
    static constexpr std::size_t kMaxShaftOccluders = 256;
    /// Per link while the patch rows are built (shaftClear): 0 not yet tested, 1 clear, 2 maybe blocked.
    mutable std::vector<std::uint8_t> linkShaft_;
    /// Per element, its quadrature nodes as a source (while refining, extendSourceRules; while the leaf
    /// and patch rows are built).
    std::vector<hierarchical::SourceRule> sourceRules_;
    std::vector<std::size_t> patchRowBegin_;
    std::vector<GatherTerm> patchRows_;
    bool patchRowsCurrent_ = false;
    std::vector<std::size_t> leafRowBegin_;  ///< per element (rows only at leaves the patches do not resolve)
    std::vector<GatherTerm> leafRows_;
    /// The patches' 3 x 3 Gauss points in patch order, each with the leaf holding it and its share of
    /// the area of the points that leaf reads (buildLeafRows).
    struct LeafPoint {
        ElementIndex leaf;
        std::uint32_t patch;
        float area;   ///< the point's Gauss weight times its patch's area
        float share;  ///< area over the summed area of the leaf's points that it reads (else zero)
    };
    std::vector<LeafPoint> leafPoints_;
    std::vector<std::uint8_t> leafFromPatches_;  ///< per element: 1 for a leaf that reads the patch rows
    std::vector<Rgb> patchIrradiance_, patchPushed_;  ///< per patch, scratch of gatherLeafRows
    /// patchIrradiance_ holds every patch row's sum at the radiosity the tree holds now: the solution's
    /// map computed it (after push-pull), and the next step's gatherLeafRows reads the same radiosity.
    /// Cleared wherever the radiosity or the rows change.
    bool patchIrradianceCurrent_ = false;
    std::vector<Rgb> leafIrradiance_;
    bool leafRowsCurrent_ = false;
    bool linksSettled_ = false;  ///< the rows were built: no refinement until materials or the view change
    bool refinedSinceChange_ = false;  ///< a step refined since the materials, the view or reset() changed
    bool settleOnResidual_ = true;  ///< kSettleResidual applies (not once the importance view changed)

    unsigned threads_ = 1;
    std::vector<std::vector<Split>> splitsPerThread_;
    std::vector<std::vector<NewLink>> linksPerThread_;
    std::vector<NewLink> produced_;
    std::vector<std::size_t> raysPerThread_;
    std::vector<Rgb> pushedIrradiance_;
    std::size_t rays_ = 0;
    IterationStats stats_;
};

/// Hierarchical settings for about `elements` leaves, for benches that scale the element count:
/// leaves no larger than a = twice the scene's area A over `elements` (a face keeps whole quarters, so
/// leaves average about half that: 9.4k leaves for 10k on the Cornell box), the oracle's threshold
///   linkEpsilon = kScaledLinkEpsilon x (a / A)^(3/2),
/// so the radiosity error a link may leave at a leaf's parent shrinks like the leaf's edge, and one
/// more level allowed where the oracle insists (shadow edges, contact with other faces). Links per
/// leaf then grow slowly with the leaves (Cornell box: 5.9, 8.8, 11.5 at 10k, 100k, 1M; at most like
/// elements^(1/3) by Hanrahan et al.'s Section 4 count with a tolerance proportional to the edge).
struct HierarchicalSetup {
    SolverOptions options;
    HierarchicalRefinement refinement;
};
/// 7 keeps the 10k-element threshold of the earlier rule linkEpsilon = 0.1 a / A.
inline constexpr double kScaledLinkEpsilon = 7;
HierarchicalSetup hierarchicalSetupForElements(const Scene& scene, std::size_t elements, SolverOptions base = {});

} // namespace radiant
