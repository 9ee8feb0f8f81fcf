// What the hierarchical solve shows between its elements: the irradiance at a point gathered over the
// links of every element that contains it, with the exact point-to-element kernel at that point,
// instead of the constant its leaf holds. This is the final gather of hierarchical radiosity
// (D. Lischinski, F. Tampieri, D. Greenberg, "Combining hierarchical radiosity and discontinuity
// meshing", SIGGRAPH 1993, Section 5; P. Hanrahan, D. Salzman, L. Aupperle 1991 push the same links'
// irradiance down as a constant): it plays the role of RenderPark's higher-order basis on the leaf
// (Gortler, Schroeder, Cohen, Hanrahan, "Wavelet radiosity", SIGGRAPH 1993), so the value at a point
// follows the kernel's variation across a leaf, most of all near contact and under the light.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "radiometry/formfactor/PointKernel.h"
#include "radiometry/solver/HierarchicalFormFactor.h"
#include "radiometry/solver/HierarchicalParallel.h"
#include "radiometry/solver/HierarchicalSolver.h"

namespace radiant {

void HierarchicalSolver::indexLinksByReceiver() {
    const std::size_t n = tree_.size();
    receiverLinkBegin_.assign(n + 1, 0);
    for (const Link& link : links_) ++receiverLinkBegin_[link.receiver + 1];
    for (std::size_t e = 0; e < n; ++e) receiverLinkBegin_[e + 1] += receiverLinkBegin_[e];
    receiverLinks_.resize(links_.size());
    std::vector<std::uint32_t> next(receiverLinkBegin_.begin(), receiverLinkBegin_.end() - 1);
    for (std::size_t i = 0; i < links_.size(); ++i) receiverLinks_[next[links_[i].receiver]++] = static_cast<std::uint32_t>(i);
}

namespace {

/// F(dx -> q): Lambert's contour integral (in float where q lies wholly above x's tangent plane:
/// pointToElementFormFactorFloat), or where q is small for its distance from x, a Gauss rule of
/// the point kernel over it by q's precomputed nodes: 2 x 2 beyond kFarFieldDistanceSquaredOverArea
/// (within 0.2% there, a quarter of the cost: the patch rows of a 2,000-patch mesh took 0.25 s of CPU
/// with the contour integral alone), 3 x 3 beyond kGaussDistanceSquaredOverArea, 5 x 5 beyond
/// kNearGaussDistanceSquaredOverArea (the Cornell box's rows made ~450k contour integrals for sources
/// within the 3 x 3 rule's distance; docs/ARCHITECTURE.md, "Accuracy", Hierarchical item 20).
double kernelAt(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& q, const hierarchical::SourceRule& rule) {
    // (|centroid - x| - sqrt(A))^2 / A against the rules' thresholds, as squared distances.
    const glm::dvec3 d = q.centroid - x;
    const double distance2 = glm::dot(d, d);
    if (distance2 > rule.nearDistance2) {
        using hierarchical::RuleOrder;
        const RuleOrder order = distance2 > rule.farDistance2 ? RuleOrder::Far : distance2 > rule.gaussDistance2 ? RuleOrder::Gauss : RuleOrder::Near;
        const double f = hierarchical::ruleFormFactor(x, n, q, rule, order);
        if (f >= 0) return f;
    }
    return hierarchical::pointToElementFormFactorFloat(x, n, q);
}

/// F(p -> q) unoccluded, for a receiver small against the link it inherits: the receiver's mean of
/// kernelAt by a 3 x 3 Gauss rule over it when close (gaussMeanKernel's rule), the far-field kernel at
/// its centroid when the source is far and the receiver small against the distance too (the kernel is
/// then nearly linear across it), else the mean at its four children's centroids. kernelAt, not
/// Lambert's integral, wherever q is small for its distance from the point (within 0.006% there; the
/// integral's four atan2 per point were most of the leaf rows' kernel time).
double meanKernelAt(const PatchPolygon& p, const PatchPolygon& q, const hierarchical::SourceRule& rule) {
    const glm::dvec3 apart = p.centroid - q.centroid;
    const double reach = std::sqrt(p.area) + std::sqrt(q.area);
    const double distance2 = glm::dot(apart, apart);
    if (distance2 < 2.25 * reach * reach) {
        double sum = 0;
        hierarchical::forGaussPoints(p, 3, [&](const glm::dvec3& x, double weight) { sum += weight * kernelAt(x, p.normal, q, rule); });
        return sum;
    }
    const double nearestSample = std::max(0.0, std::sqrt(distance2) - std::sqrt(p.area));
    const bool far = nearestSample * nearestSample > hierarchical::kFarFieldDistanceSquaredOverArea * q.area;
    if (far && distance2 > hierarchical::kFarFieldDistanceSquaredOverArea * p.area) {
        const double f = hierarchical::ruleFormFactor(p.centroid, p.normal, q, rule, true);
        if (f >= 0) return f;
    }
    double sum = 0;
    for (const glm::dvec3& x : hierarchical::childCentroids(p)) sum += kernelAt(x, p.normal, q, rule);
    return 0.25 * sum;
}

/// Whether x (unit normal n) may see some of q's front: x in front of q's plane and some corner of q
/// above x's tangent plane. The kernel is zero otherwise; a cheap test before the kernel itself.
bool mayFace(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& q) {
    if (glm::dot(q.normal, x - q.centroid) <= 0) return false;
    for (const glm::dvec3& v : q.corners())
        if (glm::dot(n, v - x) > 0) return true;
    return false;
}

/// Some of the link's rays got through and some did not, in either of its two sets (the oracle's or
/// the share's).
bool partlyVisible(const Link& link, float share) { return link.partiallyVisible() || (share > 0 && share < 1); }

/// Rays per term whose link's share does not stand for it, in the leaf and patch rows (cast once,
/// when the rows are built).
constexpr int kTermVisibilityRays = 8;
/// The same in the patch rows for a term that brings the patch under kBrightHidden of its light:
/// 8 and 4 gave the bench's points the same errors (0.24% / 1.1% mean / worst at seed 1), and such
/// terms are most of the rows' rays.
constexpr int kDimTermVisibilityRays = 4;
/// Rays for a dim term of a patch row by the share w of the patch's irradiance it brings (see
/// `shareOfIrradiance` in buildPatchRows): the error its visibility leaves in the patch's irradiance
/// has variance w^2 v (1 - v) / n for n rays and a visible share v, so for a given number of rays the
/// row's variance is least with n in proportion to w (J. Neyman's allocation, "On the two different
/// aspects of the representative method", J. Royal Statistical Society 1934). Four rays for every dim
/// term spent 42% of the Cornell box's dim sets on terms under 0.1% of the patch's light, which hold
/// 2% of it. With one ray under kFaintTerm and two under kDimTerm the patches moved from converged
/// Gauss-Seidel (64 rays) by 0.605% -> 0.640% on average over 12 seeds, for 14% less CPU
/// (docs/ARCHITECTURE.md, "Accuracy", item 22). One ray reads the plain share of area pairs, not the
/// kernel-weighted one (a single weight cancels): they differ near a blocker's foot, in terms that
/// hold a thousandth of the patch's light each.
constexpr double kFaintTerm = 1e-3;
constexpr double kDimTerm = 3e-3;
int dimTermRays(double share) { return share < kFaintTerm ? 1 : share < kDimTerm ? 2 : kDimTermVisibilityRays; }
/// Rays a bright term (a piece of the lamp) casts from the patch after its first kTermVisibilityRays
/// found `seen` of it: where it is in a penumbra (its link partly visible, or the rays disagreeing with
/// each other or with the link's own verdict) 56 more for a term that brings the patch kFullPenumbra of
/// its light or more, fewer in proportion to its share below that (at least 8, by the same allocation
/// as dimTermRays); 24 more where the link's rays found the source hidden and so did the patch's (a
/// sliver of the lamp in sight: 24 rays find a share of 8% 86% of the time), none where the patch's
/// rays confirm a fully visible link. Eight rays alone left the Cornell box's floor patches in the
/// blocks' penumbrae 20-70% off converged Gauss-Seidel, some always dark (docs/ARCHITECTURE.md,
/// "Accuracy", item 16).
constexpr double kFullPenumbra = 0.1;
int penumbraRays(const Link& link, float share, double seen, double ofIrradiance) {
    if (partlyVisible(link, share) || (seen > 0 && seen < 1) || (link.formFactor > 0 && seen != static_cast<double>(share)))
        return std::max(8, static_cast<int>(std::lround(56 * std::min(1.0, ofIrradiance / kFullPenumbra))));
    return link.formFactor <= 0 ? 24 : 0;
}
/// A link whose receiver is more than this many times the patch's area gives the patch no share of
/// its own: the patch's terms cast rays.
constexpr double kLargeReceiver = 15;
/// See gatherTermsAt.
constexpr double kBrightHidden = 0.01;
/// Terms of a patch's row whose squared distance from the patch's centroid exceeds this times the
/// patch's area take their kernel from one point, scaled so that the far terms of a link sum to what
/// the link's whole source gives over the patch's points (expandSourceScaled): the patch's extent
/// changes a far term's kernel by a factor within a few percent of one and nearly the same for the
/// terms of one source, so only their ratios carry what is left of it. The bench's points and the
/// patches' distance from converged Gauss-Seidel (seeds 1-6) came out the same at 16, 4 and 1.
constexpr double kFarTermDistanceSquaredOverArea = 4;

/// A far term's estimate for expandSourceScaled: the point-to-point kernel from x to q's centroid,
/// A cos cos / (pi r^2). Only the ratios of a link's far terms count (their sum is the whole source's
/// kernel at the patch's points), and the one point's bias is nearly the same for a link's far terms.
/// kernelAt's Gauss rule read each term's source rule (~700 bytes an element, scattered) for most of
/// the Cornell box's ~1.05M row terms: without it the solve's CPU is ~7% lower and the patches within
/// 0.0015 percentage points of before (docs/ARCHITECTURE.md, "Accuracy", Hierarchical item 19).
double centroidKernel(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& q) {
    return q.area * pointToPointKernel(x, n, q.centroid, q.normal);
}

/// Whether a gather at x reads `source` through its children: area over squared distance above
/// `expansion` (HierarchicalSolver::kSourceExpansion; expandSource says why).
bool readThroughChildren(const ElementTree& tree, ElementIndex source, const glm::dvec3& x, double expansion) {
    const PatchPolygon& q = tree.polygon(source);
    const glm::dvec3 d = q.centroid - x;
    return !tree.isLeaf(source) && q.area > expansion * glm::dot(d, d);
}

} // namespace

template <class Faces, class Expand>
void HierarchicalSolver::gatherTerms(ElementIndex leaf, const glm::dvec3& x, Faces&& faces, Expand&& expand, bool everyLink) const {
    const auto& radiosity = tree_.radiosity();
    // A link all of whose rays were blocked may still light part of x's leaf (4 rays all miss a
    // visible fraction v with chance (1 - v)^4): where its source could bring x more than
    // kBrightHidden of the leaf's irradiance, x's gather keeps it, and its visibility says.
    const double leafIrradiance = leaf < pushedIrradiance_.size() ? maxBand(pushedIrradiance_[leaf]) : 0.0;
    const auto brightHidden = [&](const Link& link) {
        const PatchPolygon& q = tree_.polygon(link.source);
        const glm::dvec3 d = q.centroid - x;
        return maxBand(radiosity[link.source]) * q.area > kBrightHidden * leafIrradiance * std::numbers::pi * glm::dot(d, d);
    };
    for (ElementIndex e = leaf; e != kNoElement; e = tree_.parent(e))
        for (std::uint32_t k = receiverLinkBegin_[e]; k < receiverLinkBegin_[e + 1]; ++k) {
            const std::uint32_t i = receiverLinks_[k];
            if (!everyLink && links_[i].formFactor <= 0 && !links_[i].partiallyVisible() && !brightHidden(links_[i])) continue;
            if (!faces(tree_.polygon(links_[i].source))) continue;
            expand(i);
        }
}

template <class Kernel, class Visibility>
void HierarchicalSolver::expandSource(std::uint32_t link, ElementIndex source, const glm::dvec3& x, Kernel& kernel,
                                      Visibility& visibility, std::vector<GatherTerm>& out) const {
    // A source large for its distance from x is read through its children: its radiosity varies
    // across it (bright under the light, dark in a corner) where x's kernel varies too, and the
    // product's mean is not the means' product. So does its visibility, and with the radiosity: the
    // floor a block hides from the ceiling is the floor in the block's shadow, so one visible share
    // for the whole source, times its children's radiosities, made the ceiling 0.8% dark.
    if (readThroughChildren(tree_, source, x, kSourceExpansion)) {
        const ElementIndex first = tree_.firstChild(source);
        for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c) expandSource(link, c, x, kernel, visibility, out);
        return;
    }
    const PatchPolygon& q = tree_.polygon(source);
    const double f = kernel(source, q);
    if (f <= 0) return;
    const double v = visibility(link, source, q);
    if (v > 0) out.push_back({source, static_cast<float>(f * v)});
}

template <class Kernel, class Estimate, class Visibility>
void HierarchicalSolver::expandSourceScaled(std::uint32_t link, const glm::dvec3& x, double farDistance2, Kernel& kernel,
                                            Estimate& estimate, Visibility& visibility, std::vector<ElementIndex>& terms,
                                            std::vector<double>& values, std::vector<GatherTerm>& out) const {
    // The terms expandSource would make: the source, or its descendants small for their distance.
    const ElementIndex root = links_[link].source;
    terms.clear();
    const auto collect = [&](const auto& self, ElementIndex source) -> void {
        if (readThroughChildren(tree_, source, x, kSourceExpansion)) {
            for (ElementIndex c = tree_.firstChild(source); c < tree_.firstChild(source) + ElementTree::kChildCount; ++c) self(self, c);
            return;
        }
        terms.push_back(source);
    };
    collect(collect, root);
    // A source's descendants made 9 in 10 of the rows' kernels (1.09M of 1.19M on the Cornell box),
    // each at the patch's four points. Far ones are estimated at one point first (values[k] < 0
    // marks them, holding -1 - estimate); the whole source at the four points then fixes their sum.
    values.resize(terms.size());
    double nearSum = 0, farSum = 0;
    std::size_t farCount = 0;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const PatchPolygon& q = tree_.polygon(terms[k]);
        const glm::dvec3 d = q.centroid - x;
        const double e = terms.size() > 1 && glm::dot(d, d) > farDistance2 ? estimate(terms[k], q) : -1.0;
        if (e >= 0) {
            values[k] = -1 - e;  // marked far
            farSum += e;
            ++farCount;
        } else {
            values[k] = kernel(terms[k], q);
            nearSum += values[k];
        }
    }
    double scale = 1;
    if (farCount > 0) {
        const double rest = farCount > 1 && farSum > 0 ? kernel(root, tree_.polygon(root)) - nearSum : -1.0;
        scale = rest >= 0 ? rest / farSum : -1.0;
    }
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const PatchPolygon& q = tree_.polygon(terms[k]);
        double f = values[k];
        // A far term without a usable whole (one far term, or round-off left the near ones more than
        // the source): its own kernel.
        if (f < 0) f = scale >= 0 ? scale * (-1 - f) : kernel(terms[k], q);
        if (f <= 0) continue;
        const double v = visibility(link, terms[k], q);
        if (v > 0) out.push_back({terms[k], static_cast<float>(f * v)});
    }
}

namespace {

/// An axis-aligned box: its low and high corners.
using Box = std::pair<glm::dvec3, glm::dvec3>;

/// The bounding box of a and b, widened by `tolerance`.
Box boxOf(const PatchPolygon& a, const PatchPolygon& b, double tolerance) {
    glm::dvec3 low = a.vertices[0], high = low;
    for (const PatchPolygon* polygon : {&a, &b})
        for (const glm::dvec3& v : polygon->corners()) {
            low = glm::min(low, v);
            high = glm::max(high, v);
        }
    return {low - glm::dvec3(tolerance), high + glm::dvec3(tolerance)};
}

/// Whether the box from `low` to `high` meets `box`.
bool boxesMeet(const glm::dvec3& low, const glm::dvec3& high, const Box& box) {
    return glm::all(glm::lessThanEqual(low, box.second)) && glm::all(glm::lessThanEqual(box.first, high));
}

} // namespace

bool HierarchicalSolver::occludersMissBoxOf(const PatchPolygon& a, const PatchPolygon& b) const {
    if (occluderBegin_.empty()) return false;
    const Box box = boxOf(a, b, shaftTolerance_);
    for (std::size_t k = 0; k + 1 < occluderBegin_.size(); ++k)
        if (boxesMeet(occluderBox_[2 * k], occluderBox_[2 * k + 1], box)) return false;
    return true;
}

bool HierarchicalSolver::shaftClear(std::uint32_t link) const {
    if (occluderBegin_.empty()) return false;
    std::atomic_ref<std::uint8_t> known(linkShaft_[link]);
    const std::uint8_t state = known.load(std::memory_order_relaxed);
    if (state != 0) return state == 1;
    // An occluder outside the pair's bounding box cannot meet their convex hull: the shaft (~0.7 us
    // to build) is built only where some occluder's box meets the pair's, and tested against those.
    const PatchPolygon& receiver = tree_.polygon(links_[link].receiver);
    const PatchPolygon& source = tree_.polygon(links_[link].source);
    const Box box = boxOf(receiver, source, shaftTolerance_);
    bool clear = true;
    std::optional<hierarchical::Shaft> shaft;
    for (std::size_t k = 0; clear && k + 1 < occluderBegin_.size(); ++k) {
        if (!boxesMeet(occluderBox_[2 * k], occluderBox_[2 * k + 1], box)) continue;
        if (!shaft) shaft.emplace(receiver, source, shaftTolerance_);
        clear = shaft->separates({occluderCorners_.data() + occluderBegin_[k], occluderBegin_[k + 1] - occluderBegin_[k]});
    }
    known.store(clear ? 1 : 2, std::memory_order_relaxed);  // two threads may both test it: the same answer
    return clear;
}

void HierarchicalSolver::buildSourceRules() {
    if (sourceRules_.size() == tree_.size()) return;
    sourceRules_.resize(tree_.size());
    parallelChunks(tree_.size(), threads(), 1024, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t e = from; e < to; ++e) sourceRules_[e] = hierarchical::makeSourceRule(tree_.polygon(static_cast<ElementIndex>(e)));
    });
}

void HierarchicalSolver::buildPatchRows() {
    patchIrradianceCurrent_ = false;
    linkShaft_.assign(occluderBegin_.empty() ? 0 : links_.size(), 0);
    buildSourceRules();
    // Chunks of 16 patches (about 70 per thread: a patch in the lamp's penumbra costs many times a
    // dark one, and with 64 one thread finished its last chunk alone), each chunk's rows appended to
    // one buffer of its own (a vector per patch grew by doubling: ~2,000 vectors' reallocations).
    constexpr std::size_t kRowChunk = 16;
    std::vector<std::vector<GatherTerm>> chunkRows((patches_.size() + kRowChunk - 1) / kRowChunk);
    std::vector<std::size_t> rowSize(patches_.size(), 0);
    const auto& radiosity = tree_.radiosity();
    parallelChunks(patches_.size(), threads(), kRowChunk, [&](std::size_t from, std::size_t to, unsigned) {
        std::vector<GatherTerm>& chunkRow = chunkRows[from / kRowChunk];
        std::vector<GatherTerm> row;  // the current patch's terms, merged, then appended to chunkRow
        // A link's visible share, the same for every point of its receiver, except where its rays
        // found it partially visible or its receiver is much larger than the patch: there visibility
        // and radiosity vary together (the floor under a sphere is in its shadow; a link from a larger
        // floor element to the lamp or a wall carries that element's mean share: the floor under the
        // sphere room's sphere was 6.5% over Gauss-Seidel with the expanded leaf rows, 2.3% with rays
        // for the partial links alone), so each such term casts rays from the patch, once per patch
        // (rays per patch point would make the display noisy; the probe's point casts its own).
        // Per element, scratch of this thread's current patch (reset through the row after each):
        // the term's visibility from the patch (negative: not yet cast) and its place in the row
        // (-1: not in it), so that merging a row's terms costs no sort.
        std::vector<double> termVisibility(tree_.size(), -1.0);
        std::vector<std::int32_t> rowSlot(tree_.size(), -1);
        std::vector<ElementIndex> cast;
        std::vector<ElementIndex> termScratch;  // expandSourceScaled's
        std::vector<double> valueScratch;
        std::vector<std::pair<ElementIndex, unsigned>> chain;  // the split patch's chains, see below
        const PatchPolygon* patchPolygon = nullptr;
        std::uint64_t patchSeed = 0;
        double patchIrradiance = 0;
        // A source that brings the patch much of its light (the lamp's pieces) is seen through the
        // patch's own rays whatever its link's verdict: four rays that all got through, or were all
        // blocked, call a penumbra lit or dark for the whole of a receiver larger than the patch.
        // The share of the patch's irradiance a term brings, roughly: the point kernel between the
        // centroids stands in for its form factor.
        const auto shareOfIrradiance = [&](ElementIndex term, const PatchPolygon& q) {
            const glm::dvec3 d = q.centroid - patchPolygon->centroid;
            const double r2 = glm::dot(d, d);
            const double cosines = std::max(0.0, glm::dot(patchPolygon->normal, d)) * std::max(0.0, -glm::dot(q.normal, d));
            const double brought = maxBand(radiosity[term]) * q.area * cosines;
            const double whole = patchIrradiance * std::numbers::pi * r2 * r2;
            return whole > 0 ? brought / whole : brought > 0 ? std::numeric_limits<double>::infinity() : 0.0;
        };
        const auto visibility = [&](std::uint32_t link, ElementIndex term, const PatchPolygon& q) {
            const bool own = !partlyVisible(links_[link], linkShare_[link]) && links_[link].formFactor > 0 &&
                             tree_.area(links_[link].receiver) <= kLargeReceiver * patchPolygon->area;
            const double share = shareOfIrradiance(term, q);
            const bool lamp = share > kBrightHidden;
            if (caster_ == nullptr || (own && !lamp)) return static_cast<double>(linkShare_[link]);
            // No face can block a segment between the link's receiver and its source (which holds the
            // term): every point of the receiver sees all of the term, no ray needed. The row takes
            // this term's kernel only at those of the patch's points that lie in the receiver (the
            // walks below reach a link through the elements holding a point), so 1 is their exact
            // visibility, also where the patch crosses the receiver's edge (requiring the receiver to
            // hold the whole patch left 39k of the Cornell box's 341k ray sets: docs/ARCHITECTURE.md,
            // "Accuracy", item 18).
            if (!partlyVisible(links_[link], linkShare_[link]) && links_[link].formFactor > 0 && shaftClear(link))
                return 1.0;
            // Rays from the patch to the term: the same whichever link of the patch's points asked.
            double& known = termVisibility[term];
            if (known < 0) {
                const std::uint64_t seed = hierarchical::mix(patchSeed ^ static_cast<std::uint64_t>(term));
                known = hierarchical::elementVisibility(*patchPolygon, q, *caster_, lamp ? kTermVisibilityRays : dimTermRays(share), seed);
                const int more = lamp ? penumbraRays(links_[link], linkShare_[link], known, share) : 0;
                if (more > 0) {
                    const double extra = hierarchical::elementVisibility(*patchPolygon, q, *caster_, more, hierarchical::mix(seed ^ 0x7e3a1ull));
                    known = (kTermVisibilityRays * known + more * extra) / (kTermVisibilityRays + more);
                }
                cast.push_back(term);
            }
            return known;
        };
        for (std::size_t p = from; p < to; ++p) {
            const PatchSample& patch = patches_[p];
            row.clear();
            for (const ElementIndex term : cast) termVisibility[term] = -1.0;
            cast.clear();
            // A covered patch (the floor under a block) sees only backs: no light reaches it, and its
            // row held nothing. Yet its irradiance, near zero, made every source "bright" to it, so
            // each of its terms cast the lamp's 32-88 rays: the Cornell box's 146 covered floor
            // patches cast 1.4M of the rows' 3.6M rays, to find what Patch::covered already says.
            if (patch.covered) continue;
            patchPolygon = &patch.polygon;
            patchSeed = hierarchical::mix(options_.seed ^ 0x9a7c4ull ^ p);
            // The patch's mean irradiance by a Gauss rule: 3 x 3 where the leaves are finer than the
            // patch (their links say the irradiance varies within it), 2 x 2 elsewhere.
            const ElementIndex atCentroid = tree_.locate(patch.surface, patch.face, patch.centroid);
            patchIrradiance = atCentroid < pushedIrradiance_.size() ? maxBand(pushedIrradiance_[atCentroid]) : 0.0;
            const int order = atCentroid != kNoElement && 4 * tree_.area(atCentroid) < patch.area ? 3 : 2;
            std::array<glm::dvec3, 4> points{};
            std::array<double, 4> weights{};
            std::size_t pointCount = 0;
            ElementIndex commonLeaf = kNoElement;
            std::array<ElementIndex, 4> leaves{};
            if (order == 2 && patch.polygon.count >= 3) {
                hierarchical::forGaussPoints(patch.polygon, 2, [&](const glm::dvec3& x, double weight) {
                    points[pointCount] = x;
                    weights[pointCount++] = weight;
                });
                for (std::size_t i = 0; i < pointCount; ++i) {
                    leaves[i] = tree_.locate(patch.surface, patch.face, points[i]);
                    commonLeaf = i == 0 || leaves[i] == commonLeaf ? leaves[i] : kNoElement;
                }
            }
            const bool wholePatch = pointCount == 4 && commonLeaf != kNoElement;
            const PatchPolygon& P = patch.polygon;
            const double farTerm = kFarTermDistanceSquaredOverArea * patch.area;
            // Whether the patch may see some of q's front (the kernel is zero otherwise): some corner of
            // the patch in front of q's plane and some corner of q above the patch's plane.
            const auto faces = [&](const glm::dvec3& n, const PatchPolygon& q) {
                bool inFront = false, above = false;
                for (const glm::dvec3& v : P.corners()) inFront = inFront || glm::dot(q.normal, v - q.centroid) > 0;
                for (const glm::dvec3& v : q.corners()) above = above || glm::dot(n, v - P.centroid) > 0;
                return inFront && above;
            };
            if (wholePatch) {
                const glm::dvec3& n = tree_.polygon(commonLeaf).normal;
                const auto kernel = [&](ElementIndex source, const PatchPolygon& q) {
                    const hierarchical::SourceRule& rule = sourceRules_[source];
                    double f = 0;
                    for (std::size_t i = 0; i < points.size(); ++i) f += weights[i] * kernelAt(points[i], n, q, rule);
                    return f;
                };
                const auto estimate = [&](ElementIndex, const PatchPolygon& q) { return centroidKernel(P.centroid, n, q); };
                gatherTerms(
                    commonLeaf, P.centroid, [&](const PatchPolygon& q) { return faces(n, q); },
                    [&](std::uint32_t link) { expandSourceScaled(link, P.centroid, farTerm, kernel, estimate, visibility, termScratch, valueScratch, row); },
                    false);
            } else if (pointCount == 4) {
                // The four points lie in different leaves, whose chains share most of their links (the
                // coarse ones): each element of the chains is walked once, with the mask of the points
                // below it, and each of its terms takes the kernel at those points (a walk, source
                // expansion and merge per point cost as much as the kernels).
                chain.clear();
                for (std::size_t i = 0; i < 4; ++i)
                    for (ElementIndex e = leaves[i]; e != kNoElement; e = tree_.parent(e)) {
                        auto it = std::find_if(chain.begin(), chain.end(), [&](const auto& c) { return c.first == e; });
                        if (it == chain.end()) chain.emplace_back(e, 1u << i);
                        else it->second |= 1u << i;
                    }
                const glm::dvec3& n = tree_.polygon(chain.front().first).normal;
                for (const auto& [e, mask] : chain) {
                    const auto kernel = [&, mask = mask](ElementIndex source, const PatchPolygon& q) {
                        const hierarchical::SourceRule& rule = sourceRules_[source];
                        double f = 0;
                        for (std::size_t i = 0; i < 4; ++i)
                            if ((mask >> i) & 1u) f += weights[i] * kernelAt(points[i], n, q, rule);
                        return f;
                    };
                    // The estimate at the points' weighted centre, with their weight.
                    double below = 0;
                    glm::dvec3 centre(0.0);
                    for (std::size_t i = 0; i < 4; ++i)
                        if ((mask >> i) & 1u) {
                            below += weights[i];
                            centre += weights[i] * points[i];
                        }
                    centre /= below;
                    const auto estimate = [&, below](ElementIndex, const PatchPolygon& q) {
                        return below * centroidKernel(centre, n, q);
                    };
                    // gatherTerms' test for a link all of whose rays were blocked, at each point below.
                    const auto brightHidden = [&, mask = mask](const Link& link) {
                        const PatchPolygon& q = tree_.polygon(link.source);
                        for (std::size_t i = 0; i < 4; ++i) {
                            if (!((mask >> i) & 1u) || leaves[i] >= pushedIrradiance_.size()) continue;
                            const glm::dvec3 d = q.centroid - points[i];
                            if (maxBand(radiosity[link.source]) * q.area >
                                kBrightHidden * maxBand(pushedIrradiance_[leaves[i]]) * std::numbers::pi * glm::dot(d, d))
                                return true;
                        }
                        return false;
                    };
                    for (std::uint32_t k = receiverLinkBegin_[e]; k < receiverLinkBegin_[e + 1]; ++k) {
                        const std::uint32_t i = receiverLinks_[k];
                        if (links_[i].formFactor <= 0 && !links_[i].partiallyVisible() && !brightHidden(links_[i])) continue;
                        if (!faces(n, tree_.polygon(links_[i].source))) continue;
                        expandSourceScaled(i, P.centroid, farTerm, kernel, estimate, visibility, termScratch, valueScratch, row);
                    }
                }
            }
            const auto gatherAt = [&](const glm::dvec3& x, double weight) {
                const ElementIndex leaf = tree_.locate(patch.surface, patch.face, x);
                if (leaf == kNoElement) return;
                const glm::dvec3& n = tree_.polygon(leaf).normal;
                const auto kernel = [&](ElementIndex source, const PatchPolygon& q) { return weight * kernelAt(x, n, q, sourceRules_[source]); };
                gatherTerms(
                    leaf, x, [&](const PatchPolygon& q) { return mayFace(x, n, q); },
                    [&](std::uint32_t link) { expandSource(link, links_[link].source, x, kernel, visibility, row); }, false);
            };
            if (pointCount != 4 && patch.polygon.count >= 3) hierarchical::forGaussPoints(patch.polygon, order, gatherAt);
            std::size_t kept = 0;
            for (const GatherTerm& term : row) {
                std::int32_t& slot = rowSlot[term.source];
                if (slot >= 0) {
                    row[static_cast<std::size_t>(slot)].weight += term.weight;
                } else {
                    slot = static_cast<std::int32_t>(kept);
                    row[kept++] = term;
                }
            }
            row.resize(kept);
            for (const GatherTerm& term : row) rowSlot[term.source] = -1;
            chunkRow.insert(chunkRow.end(), row.begin(), row.end());
            rowSize[p] = kept;
        }
    });
    patchRowBegin_.assign(patches_.size() + 1, 0);
    for (std::size_t p = 0; p < patches_.size(); ++p) patchRowBegin_[p + 1] = patchRowBegin_[p] + rowSize[p];
    patchRows_.clear();
    patchRows_.reserve(patchRowBegin_.back());
    for (const auto& chunkRow : chunkRows) patchRows_.insert(patchRows_.end(), chunkRow.begin(), chunkRow.end());
    patchRowsCurrent_ = true;
    sourceRules_ = {};
}

Rgb HierarchicalSolver::patchRowIrradiance(std::size_t patch) const {
    const auto& radiosity = tree_.radiosity();
    Rgb irradiance(0.0);
    for (std::size_t k = patchRowBegin_[patch]; k < patchRowBegin_[patch + 1]; ++k)
        irradiance += static_cast<double>(patchRows_[k].weight) * radiosity[patchRows_[k].source];
    return irradiance;
}

Rgb HierarchicalSolver::gatheredRadiosity(std::size_t patch) const {
    Rgb irradiance = patchIrradiance_[patch];
    const std::uint32_t s = patches_[patch].surface;
    if (!patchDirect_.empty()) irradiance += patchDirect_[patch];
    return surfaceExitance_[s] + surfaceReflectance_[s] * irradiance;
}

Rgb HierarchicalSolver::radiosityAt(std::uint32_t surface, std::uint32_t face, const glm::dvec3& point) const {
    const ElementIndex leaf = tree_.locate(surface, face, point);
    if (leaf == kNoElement) return Rgb(0.0);
    if (stats_.iteration == 0) return tree_.radiosity()[leaf];  // before the first step: B = E
    const PatchPolygon& element = tree_.polygon(leaf);
    // On the element's plane: a probe point may lie a hair off it.
    const glm::dvec3 x = point - glm::dot(point - element.centroid, element.normal) * element.normal;
    std::vector<GatherTerm> terms;
    // Every term casts its own rays from x: a link's four rays may have called a penumbra fully lit
    // or fully dark, which the point would inherit.
    const auto rays = [&](std::uint32_t link, ElementIndex term, const PatchPolygon& q) {
        if (caster_ == nullptr) return static_cast<double>(linkShare_[link]);
        return hierarchical::pointVisibility(x, element.normal, q, *caster_, kPointVisibilityRaysPerSide,
                                             hierarchical::mix(options_.seed ^ link) ^ hierarchical::mix(term));
    };
    const auto kernel = [&](ElementIndex, const PatchPolygon& q) { return hierarchical::pointToElementFormFactor(x, element.normal, q); };
    gatherTerms(
        leaf, x, [&](const PatchPolygon& q) { return mayFace(x, element.normal, q); },
        [&](std::uint32_t link) { expandSource(link, links_[link].source, x, kernel, rays, terms); }, caster_ != nullptr);
    Rgb irradiance(0.0);
    for (const GatherTerm& term : terms) irradiance += static_cast<double>(term.weight) * tree_.radiosity()[term.source];
    if (lighting_) irradiance += lighting_->at(x, element.normal).value();
    return surfaceExitance_[surface] + surfaceReflectance_[surface] * irradiance;
}

void HierarchicalSolver::buildLeafRows() {
    const std::size_t n = tree_.size();
    buildSourceRules();  // kept for the patch rows, built last
    // A leaf reads the patch rows where the patches resolve it: their rows already gather each patch's
    // terms with its own kernel and visibility (per-term rays for the lamp's pieces and partial links,
    // which a leaf's own row takes from its links' shares), and built from the leaf itself they were
    // a second set of kernels and rays for the same surface (a fifth of the Cornell box's solve).
    // Patches and elements are cut independently, so most patches straddle leaves: each leaf takes its
    // patches' values at the Gauss points inside it (gatherLeafRows).
    // A patch much larger than the leaf would hand it the patch's mean, its variation across the
    // patch only as far as the links' pushed values carry it (gatherLeafRows): such a leaf keeps its
    // own row (the furnace meshed at 0.1 m^2 with 1,536 leaves: with patches up to 4x the leaf read,
    // every leaf within 0.13% of E / (1 - rho); with patches up to 16x, 3.2%).
    const auto resolves = [&](double patchArea, ElementIndex leaf) { return patchArea <= kPatchOverLeaf * tree_.area(leaf); };
    // The points' leaves on both cores (25k locates on the Cornell box, ~5 ms on one), then gathered
    // in patch order, as one loop made them.
    constexpr std::size_t kPointsPerPatch = 9;
    std::vector<LeafPoint> located(kPointsPerPatch * patches_.size(), LeafPoint{kNoElement, 0, 0.0f, 0.0f});
    std::vector<double> pointWeight(located.size(), 0.0);
    parallelChunks(patches_.size(), threads(), 64, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t p = from; p < to; ++p) {
            const PatchSample& patch = patches_[p];
            if (patch.polygon.count < 3) continue;
            std::size_t k = kPointsPerPatch * p;
            hierarchical::forGaussPoints(patch.polygon, 3, [&](const glm::dvec3& x, double weight) {
                located[k] = {tree_.locate(patch.surface, patch.face, x), static_cast<std::uint32_t>(p),
                              static_cast<float>(weight * patch.area), 0.0f};
                pointWeight[k++] = weight;
            });
        }
    });
    leafPoints_.clear();
    std::vector<double> resolvedArea(n, 0.0);
    for (std::size_t k = 0; k < located.size(); ++k) {
        const LeafPoint& point = located[k];
        if (point.leaf == kNoElement) continue;
        leafPoints_.push_back(point);
        const double area = patches_[point.patch].area;
        if (resolves(area, point.leaf)) resolvedArea[point.leaf] += pointWeight[k] * area;
    }
    leafFromPatches_.assign(n, 0);
    for (std::size_t e = 0; e < n; ++e) leafFromPatches_[e] = resolvedArea[e] > 0 ? 1 : 0;
    for (LeafPoint& point : leafPoints_)
        if (resolves(patches_[point.patch].area, point.leaf)) point.share = static_cast<float>(point.area / resolvedArea[point.leaf]);
    std::vector<std::vector<GatherTerm>> rows(n);
    struct Term {
        ElementIndex source;
        double kernel, visible;
    };
    // Chunks of 16 elements: the leaves with rows of their own are a few dozen to a few hundred,
    // bunched together in the tree's order (chunks of 256 left one thread to build most of them).
    parallelChunks(n, threads(), 16, [&](std::size_t from, std::size_t to, unsigned) {
        std::vector<Term> terms;
        for (std::size_t i = from; i < to; ++i) {
            const auto leaf = static_cast<ElementIndex>(i);
            if (!tree_.isLeaf(leaf) || leafFromPatches_[leaf]) continue;
            const PatchPolygon& p = tree_.polygon(leaf);
            std::vector<GatherTerm>& row = rows[i];
            const double leafIrradiance = leaf < pushedIrradiance_.size() ? maxBand(pushedIrradiance_[leaf]) : 0.0;
            for (ElementIndex e = leaf; e != kNoElement; e = tree_.parent(e))
                for (std::uint32_t k = receiverLinkBegin_[e]; k < receiverLinkBegin_[e + 1]; ++k) {
                    const Link& link = links_[receiverLinks_[k]];
                    if (link.formFactor <= 0) continue;
                    // The leaf takes each link's form factor from itself (an ancestor's link holds the
                    // ancestor's mean), and reads a source that is large for its distance through its
                    // children, as expandSource does at a point: its radiosity varies across it where
                    // the leaf's kernel does, and the product's mean is not the means' product. That
                    // holds for the leaf's own links too: a sphere's underside facet, a root of 0.001
                    // m^2 linked to the floor's root (F ~ 0.96), read the floor's mean radiosity, twice
                    // that of the floor in the sphere's shadow beneath it (+9%), and the link's BF
                    // error is far below any threshold, so refinement never split it.
                    const bool own = e == leaf;
                    const double share = linkShare_[receiverLinks_[k]];
                    // A partially visible link's one share is wrong for its source's children and
                    // for a leaf below its receiver: visibility and radiosity vary together (the
                    // floor a block hides from the ceiling is the floor in its shadow), so such a
                    // term casts its own rays from the leaf (an unbiased estimate, as the link's).
                    const bool perTerm = caster_ && partlyVisible(link, linkShare_[receiverLinks_[k]]);
                    const auto add = [&](const auto& self, ElementIndex q) -> void {
                        const PatchPolygon& polygon = tree_.polygon(q);
                        const glm::dvec3 d = polygon.centroid - p.centroid;
                        if (!tree_.isLeaf(q) && polygon.area > kSourceExpansion * glm::dot(d, d)) {
                            for (ElementIndex c = tree_.firstChild(q); c < tree_.firstChild(q) + ElementTree::kChildCount; ++c)
                                self(self, c);
                            return;
                        }
                        if (own && q == link.source) {
                            terms.push_back({q, link.formFactor, 1});
                            return;
                        }
                        const double f = meanKernelAt(p, polygon, sourceRules_[q]);
                        if (f <= 0) return;
                        // A term that brings the leaf under kBrightHidden of its light casts the patch
                        // rows' fewer rays for dim terms.
                        const bool dim = maxBand(tree_.radiosity()[q]) * f < kBrightHidden * leafIrradiance;
                        const double v = perTerm ? hierarchical::elementVisibility(p, polygon, *caster_, dim ? kDimTermVisibilityRays : kTermVisibilityRays,
                                                                                   hierarchical::mix(options_.seed ^ 0x1eafull ^ ((static_cast<std::uint64_t>(leaf) << 32) | q)))
                                                 : share;
                        terms.push_back({q, f, v});
                    };
                    terms.clear();
                    add(add, link.source);
                    // An own link split over its source's children keeps its unoccluded form factor
                    // (a uniform source, as in the furnace, gathers what the link did).
                    double scale = 1;
                    if (own && !(terms.size() == 1 && terms[0].source == link.source)) {
                        double sum = 0;
                        for (const Term& t : terms) sum += t.kernel;
                        if (sum > 0 && share > 0) scale = link.formFactor / share / sum;
                    }
                    for (const Term& t : terms)
                        if (t.kernel * t.visible > 0) row.push_back({t.source, static_cast<float>(scale * t.kernel * t.visible)});
                }
        }
    });
    leafRowBegin_.assign(n + 1, 0);
    for (std::size_t e = 0; e < n; ++e) leafRowBegin_[e + 1] = leafRowBegin_[e] + rows[e].size();
    leafRows_.clear();
    leafRows_.reserve(leafRowBegin_.back());
    for (const auto& row : rows) leafRows_.insert(leafRows_.end(), row.begin(), row.end());
    leafIrradiance_.assign(n, Rgb(0.0));
    if (!patchRowsCurrent_) buildPatchRows();
    leafRowsCurrent_ = true;
}

void HierarchicalSolver::gatherLeafRows() {
    const auto& radiosity = tree_.radiosity();
    const std::size_t n = tree_.size();
    patchIrradiance_.resize(patches_.size());
    if (!patchIrradianceCurrent_)
        parallelChunks(patches_.size(), threads(), 256, [&](std::size_t from, std::size_t to, unsigned) {
            for (std::size_t p = from; p < to; ++p) patchIrradiance_[p] = patchRowIrradiance(p);
        });
    // A patch's row is its mean over the patch, and the leaves it straddles differ (one in a shadow,
    // one out): each leaf takes its own pushed irradiance (the links' value over it, from the last
    // push-pull) plus the patches' rows less the pushed irradiance averaged over the same patch, so
    // that the patch's mean blurs only what the links did not already resolve. Where a leaf holds
    // whole patches, that is the mean of their rows. (The patches' mean rows alone: the patches'
    // distance from converged Gauss-Seidel 0.91-0.95% at seeds 1-3 against 0.80-0.85% with this.)
    const bool pushed = pushedIrradiance_.size() == n;
    patchPushed_.assign(patches_.size(), Rgb(0.0));
    if (pushed) {
        std::vector<double> area(patches_.size(), 0.0);
        for (const LeafPoint& point : leafPoints_) {
            patchPushed_[point.patch] += static_cast<double>(point.area) * pushedIrradiance_[point.leaf];
            area[point.patch] += point.area;
        }
        for (std::size_t p = 0; p < patches_.size(); ++p)
            if (area[p] > 0) patchPushed_[p] /= area[p];
    }
    parallelChunks(n, threads(), 1024, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t e = from; e < to; ++e) {
            if (leafFromPatches_[e]) {
                leafIrradiance_[e] = pushed ? pushedIrradiance_[e] : Rgb(0.0);
                continue;
            }
            Rgb sum(0.0);
            for (std::size_t k = leafRowBegin_[e]; k < leafRowBegin_[e + 1]; ++k)
                sum += static_cast<double>(leafRows_[k].weight) * radiosity[leafRows_[k].source];
            leafIrradiance_[e] = sum;
        }
    });
    for (const LeafPoint& point : leafPoints_)
        if (point.share > 0)
            leafIrradiance_[point.leaf] += static_cast<double>(point.share) * (patchIrradiance_[point.patch] - patchPushed_[point.patch]);
}

} // namespace radiant
