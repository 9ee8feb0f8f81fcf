// Hierarchical radiosity: P. Hanrahan, D. Salzman, L. Aupperle, "A rapid hierarchical radiosity
// algorithm", SIGGRAPH 1991 (BF refinement, push-pull), with visibility estimated by a few rays per
// link as in their paper's Section 5.
#include "radiometry/solver/HierarchicalSolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "radiometry/common/Error.h"
#include "radiometry/solver/HierarchicalFormFactor.h"
#include "radiometry/solver/HierarchicalParallel.h"
#include "radiometry/solver/ReceiverShape.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

namespace {

std::uint64_t linkPairSeed(std::uint64_t seed, ElementIndex receiver, ElementIndex source) {
    return hierarchical::mix(seed ^ ((static_cast<std::uint64_t>(receiver) << 32) | source));
}

} // namespace

HierarchicalSolver::HierarchicalSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                       Progress* progress, HierarchicalRefinement refinement)
    : options_(options), refinement_(refinement), tree_(scene, mesh.contactCuts.get()), threads_(hierarchicalThreadCount()) {
    if (!(options.minElementArea >= 0) || !(options.linkEpsilon >= 0) || !(refinement.maxLeafArea >= 0))
        throw RadiantError({scene.name, "hierarchical options"},
                           "minElementArea, linkEpsilon and maxLeafArea must be >= 0 (got " +
                               std::to_string(options.minElementArea) + ", " + std::to_string(options.linkEpsilon) +
                               " and " + std::to_string(refinement.maxLeafArea) + ")");
    for (const Surface& surface : scene.surfaces) {
        if (surface.material >= scene.materials.size())
            throw RadiantError({scene.name, "surface '" + surface.name + "'"},
                               "material index " + std::to_string(surface.material) + " out of range (" +
                                   std::to_string(scene.materials.size()) + " materials)");
        surfaceReflectance_.push_back(scene.materials[surface.material].reflectance);
        surfaceExitance_.push_back(scene.materials[surface.material].exitance.value());
    }
    visibilityRays_ = std::min(options.formFactors.visibilityRays, kLinkVisibilityRays);
    sceneRays_ = options.rays;
    if (!sceneRays_ && (visibilityRays_ > 0 || !scene.lights.empty()))
        sceneRays_ = std::make_shared<const RayCaster>(scene);
    if (visibilityRays_ > 0) caster_ = sceneRays_;
    if (!scene.lights.empty()) lighting_ = std::make_unique<DirectLighting>(scene, sceneRays_.get());

    std::size_t faceCount = 0;
    for (const Surface& surface : scene.surfaces) faceCount += surface.faces.size();
    if (caster_ && faceCount <= kMaxShaftOccluders) {
        // The shafts test the faces that can block a segment between two of the scene's points (a
        // room's walls, floor and ceiling cannot: RayCaster::mayBlock), as the rays do: in the Cornell
        // box the blocks' 10 of its 24 faces; a shaft against each face was ~4% of the solve.
        glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
        occluderBegin_.push_back(0);
        std::size_t index = 0;
        for (const Surface& surface : scene.surfaces)
            for (const Face& face : surface.faces) {
                for (const glm::dvec3& v : face.vertices) {
                    low = glm::min(low, v);
                    high = glm::max(high, v);
                }
                if (!caster_->mayBlock(index++) || face.vertices.empty()) continue;
                occluderCorners_.insert(occluderCorners_.end(), face.vertices.begin(), face.vertices.end());
                occluderBegin_.push_back(static_cast<std::uint32_t>(occluderCorners_.size()));
                glm::dvec3 faceLow = face.vertices.front(), faceHigh = face.vertices.front();
                for (const glm::dvec3& v : face.vertices) {
                    faceLow = glm::min(faceLow, v);
                    faceHigh = glm::max(faceHigh, v);
                }
                occluderBox_.push_back(faceLow);
                occluderBox_.push_back(faceHigh);
            }
        shaftTolerance_ = 1e-7 * glm::length(high - low);
    }

    patches_.reserve(mesh.patches.size());
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& patch = mesh.patches[i];
        // A mesh made by hand may give a patch no corners: it then shows the element under its centroid.
        patches_.push_back({patch.surface, patch.face, patch.centroid, patch.area,
                            patch.cornerCount >= 3 ? mesh.polygon(i) : PatchPolygon{}, patch.covered});
    }
    for (const PatchSample& patch : patches_)
        if (patch.surface >= scene.surfaces.size() || patch.face >= scene.surfaces[patch.surface].faces.size())
            throw RadiantError({scene.name, "patch mesh"}, "a patch names surface " + std::to_string(patch.surface) +
                                                               ", face " + std::to_string(patch.face) +
                                                               ", which the scene does not have");

    splitsPerThread_.resize(threads_);
    linksPerThread_.resize(threads_);
    if (refinement.maxLeafArea > 0) splitLeavesLargerThan(refinement.maxLeafArea);
    setLeavesToEmission();  // before linking: the hidden-link check weighs each link by its source's B
    hiddenCheckThreshold_ = refinementThreshold();
    extendSourceRules();
    linkRoots(progress);  // sorted afterwards: the order does not depend on scheduling
    mapSolution(false);
}

HierarchicalSolver::~HierarchicalSolver() = default;

void HierarchicalSolver::splitLeavesLargerThan(double area) {
    // Children follow their parents, so one forward sweep also visits the children it creates.
    for (ElementIndex e = 0; e < tree_.size(); ++e)
        if (tree_.isLeaf(e) && tree_.area(e) > area) tree_.subdivide(e);
}

void HierarchicalSolver::linkRoots(Progress* progress) {
    const auto roots = tree_.roots();
    if (progress) {
        progress->total = roots.size();
        progress->done = 0;
    }
    for (auto& buffer : linksPerThread_) buffer.clear();
    raysPerThread_.assign(threads_, 0);
    parallelChunks(roots.size(), threads_, 1, [&](std::size_t begin, std::size_t end, unsigned thread) {
        for (std::size_t i = begin; i < end; ++i) {
            if (progress) progress->checkCancelled();
            for (const ElementIndex source : roots)
                if (source != roots[i]) raysPerThread_[thread] += makeLink(roots[i], source, linksPerThread_[thread]);
            if (progress) progress->done.fetch_add(1, std::memory_order_relaxed);
        }
    });
    std::vector<NewLink> made;
    for (auto& buffer : linksPerThread_) made.insert(made.end(), buffer.begin(), buffer.end());
    for (const std::size_t rays : raysPerThread_) rays_ += rays;
    // The same order whatever the thread timing: results do not depend on scheduling.
    std::sort(made.begin(), made.end(), [](const NewLink& a, const NewLink& b) {
        return a.link.receiver != b.link.receiver ? a.link.receiver < b.link.receiver : a.link.source < b.link.source;
    });
    for (const NewLink& m : made) {
        links_.push_back(m.link);
        linkShare_.push_back(m.share);
        linkShape_.push_back(m.shape);
    }
}

std::size_t HierarchicalSolver::makeLink(ElementIndex receiver, ElementIndex source, std::vector<NewLink>& out) const {
    const PatchPolygon& p = tree_.polygon(receiver);
    const PatchPolygon& q = tree_.polygon(source);
    if (!hierarchical::facing(p, q)) return 0;
    const auto [f, spread, atChildren] = hierarchical::linkKernel(p, q, source < sourceRules_.size() ? &sourceRules_[source] : nullptr);
    if (f <= 0) {
        // No sample point is in front of the source, yet part of the receiver is: the link carries
        // nothing yet, and refinement finds the part that does see the source.
        double bound = 0;
        for (const glm::dvec3& corner : p.corners())
            bound = std::max(bound, hierarchical::pointToElementFormFactor(0.999 * corner + 0.001 * p.centroid,
                                                                           p.normal, q));
        if (bound > 0) out.push_back({{receiver, source, 0.0f, static_cast<float>(bound)}, 0.0f, {}});
        return 0;
    }
    // Every link casts its own rays, refined or not, in two independent sets: one tells the oracle
    // whether the link is fully visible, hidden or partial (and so whether it refines), the other gives
    // its visible share. Promoting a link refined from a fully visible parent to fully visible on one
    // ray, as an earlier version did after Hanrahan et al.'s Section 5, estimated v (2 - v) for a true
    // fraction v; taking the share from the rays that also decided to stop refining is biased too (a
    // link stops on "all hidden" more readily than on "all visible": a half-blocked receiver came out
    // 2% dark). With independent sets the share is unbiased whatever the oracle decided.
    std::size_t rays = 0;
    double visible = 1, share = 1;
    bool hiddenButSeen = false;
    // A pair that no occluder's bounding box meets sees all of itself: the rays would all get through
    // (most of the Cornell box's links between its walls, ceiling and floor).
    if (caster_ && !occludersMissBoxOf(p, q)) {
        const std::uint64_t seed = linkPairSeed(options_.seed, receiver, source);
        visible = hierarchical::elementVisibility(p, q, *caster_, visibilityRays_, seed, &rays);
        // Every ray blocked stops refinement, yet 4 rays all miss a visible fraction v with chance
        // (1 - v)^4 (0.4 at v = 0.2): the floor's elements along the tall block's shadow, partly lit,
        // came out hidden and unrefined, and the patches on them 50-68% dark. Where the link would
        // refine were it partial (its error with the whole form factor uncertain is over the
        // threshold), more rays confirm the verdict; any that gets through makes it partial.
        if (visible <= 0 && linkError({receiver, source, static_cast<float>(f), -static_cast<float>(f)}) > hiddenCheckThreshold_ &&
            hierarchical::elementVisibility(p, q, *caster_, kHiddenCheckRays, hierarchical::mix(seed ^ 0x2545f491ull), &rays) > 0)
            hiddenButSeen = true;
        share = hierarchical::elementVisibility(p, q, *caster_, visibilityRays_, hierarchical::mix(seed ^ 0x5bd1e995ull), &rays);
    }
    // Partly visible: the visible share may vary across the receiver by the whole form factor.
    // Fully hidden: only a gap the rays missed could carry light.
    const bool partial = (visible > 0 && visible < 1) || hiddenButSeen;
    const double uncertainty = partial ? std::max(f, spread) : visible <= 0 ? kHiddenErrorWeight * spread : spread;
    std::array<float, 4> shape{};
    for (std::size_t c = 0; c < shape.size(); ++c) shape[c] = static_cast<float>(atChildren[c] * share);
    out.push_back({{receiver, source, static_cast<float>(f * share), static_cast<float>(partial ? -uncertainty : uncertainty)},
                   static_cast<float>(share), shape});
    return rays;
}

void HierarchicalSolver::extendSourceRules() {
    if (tree_.size() > kMaxElementsWithLinkRules) {
        sourceRules_ = {};
        return;
    }
    const std::size_t first = sourceRules_.size();
    if (first >= tree_.size()) return;
    // Room for the tree's growth at once (a reallocation moved every rule, ~1.2 KB each, to freshly
    // faulted pages: ~5 ms of one core over the Cornell box's refining passes), and small chunks:
    // a pass adds a few dozen to a few hundred elements.
    if (sourceRules_.capacity() < tree_.size())
        sourceRules_.reserve(std::min(kMaxElementsWithLinkRules, std::max<std::size_t>(4096, 2 * tree_.size())));
    sourceRules_.resize(tree_.size());
    parallelChunks(tree_.size() - first, threads_, 16, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t e = first + from; e < first + to; ++e)
            sourceRules_[e] = hierarchical::makeSourceRule(tree_.polygon(static_cast<ElementIndex>(e)));
    });
}

double HierarchicalSolver::emittedPower() const {
    Rgb power(0.0);
    for (const ElementIndex root : tree_.roots()) power += tree_.area(root) * elementSource(root);
    return maxBand(power);
}

double HierarchicalSolver::meanReflectance(ElementIndex e) const {
    const Rgb& rho = surfaceReflectance_[tree_.surface(e)];
    return (rho.x + rho.y + rho.z) / 3.0;
}

double HierarchicalSolver::refinementThreshold() const { return options_.linkEpsilon * emittedPower(); }

double HierarchicalSolver::linkError(const Link& link) const {
    const double geometric = link.uncertainty() * tree_.area(link.receiver);
    if (geometric <= 0) return 0;
    const Rgb& rhoP = surfaceReflectance_[tree_.surface(link.receiver)];
    const auto& radiosity = tree_.radiosity();
    if (importance_.empty()) return geometric * maxBand(rhoP * radiosity[link.source]);
    // Importance-driven (Smits, Arvo, Salesin 1992): the error of the radiosity this link brings to
    // the receiver, weighted by the receiver's importance, plus the error of the importance it
    // brings, weighted by the receiver's radiosity.
    const Rgb weighted = rhoP * radiosity[link.source] * importance_[link.receiver] +
                         meanReflectance(link.source) * importance_[link.source] * radiosity[link.receiver];
    return geometric * maxBand(weighted);
}

bool HierarchicalSolver::canSplit(ElementIndex e) const {
    // Splitting never makes an element smaller than minElementArea.
    return tree_.area(e) * 0.25 >= options_.minElementArea;
}

std::size_t HierarchicalSolver::refine() {
    const double threshold = refinementThreshold();
    hiddenCheckThreshold_ = threshold;
    std::size_t created = 0;
    std::size_t begin = 0;
    bool anySplit = false;
    raysPerThread_.assign(threads_, 0);
    std::vector<Split> splits;
    extendSourceRules();  // the rows drop them; refinement resumes after a material or view change
    for (;;) {
        // 1. Which links are too coarse (in parallel; reads only).
        for (auto& buffer : splitsPerThread_) buffer.clear();
        parallelChunks(links_.size() - begin, threads_, 8192, [&](std::size_t from, std::size_t to, unsigned thread) {
            for (std::size_t i = begin + from; i < begin + to; ++i) {
                const Link& link = links_[i];
                if (linkError(link) <= threshold) continue;
                // The kernel is exact over the source, so splitting a source only helps where its
                // radiosity varies (it has children) or where visibility varies across it; else
                // it would just share one error among more links. Otherwise split the larger.
                const bool sourceHelps = (link.partiallyVisible() || !tree_.isLeaf(link.source)) && canSplit(link.source);
                const bool receiverLarger = tree_.area(link.receiver) >= tree_.area(link.source);
                if (canSplit(link.receiver) && (receiverLarger || !sourceHelps))
                    splitsPerThread_[thread].push_back({i, true});
                else if (sourceHelps)
                    splitsPerThread_[thread].push_back({i, false});
            }
        });
        splits.clear();
        for (const auto& buffer : splitsPerThread_) splits.insert(splits.end(), buffer.begin(), buffer.end());
        if (splits.empty()) break;
        anySplit = true;
        std::sort(splits.begin(), splits.end(), [](const Split& a, const Split& b) { return a.link < b.link; });

        // 2. Split the elements (serially: the tree's arrays grow).
        for (const Split& split : splits) {
            const Link& link = links_[split.link];
            const ElementIndex e = split.splitReceiver ? link.receiver : link.source;
            if (tree_.isLeaf(e)) {
                tree_.subdivide(e);
                onSubdivided(e);
            }
        }
        extendSourceRules();

        // 3. Replace each split link by its four children (in parallel: form factors and rays). Each
        //    split owns four slots, so the links land in the same order whatever the scheduling.
        produced_.assign(ElementTree::kChildCount * splits.size(), NewLink{});
        // Chunks of up to 64 splits, about 8 per thread: 30 of the Cornell box's 41 passes have under
        // 64 splits, and with a fixed chunk of 64 each ran on one core.
        const std::size_t chunk = std::clamp<std::size_t>(splits.size() / (8 * std::size_t{threads_}), 1, 64);
        parallelChunks(splits.size(), threads_, chunk, [&](std::size_t from, std::size_t to, unsigned thread) {
            std::vector<NewLink>& scratch = linksPerThread_[thread];
            for (std::size_t i = from; i < to; ++i) {
                scratch.clear();
                const Link& link = links_[splits[i].link];
                if (splits[i].splitReceiver) {
                    const ElementIndex first = tree_.firstChild(link.receiver);
                    for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c)
                        raysPerThread_[thread] += makeLink(c, link.source, scratch);
                } else {
                    const ElementIndex first = tree_.firstChild(link.source);
                    for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c)
                        raysPerThread_[thread] += makeLink(link.receiver, c, scratch);
                }
                std::copy(scratch.begin(), scratch.end(), produced_.begin() + ElementTree::kChildCount * i);
            }
        });
        for (const Split& split : splits) links_[split.link].receiver = kNoElement;
        begin = links_.size();
        for (const NewLink& made : produced_)
            if (made.link.receiver != kNoElement) {
                links_.push_back(made.link);
                linkShare_.push_back(made.share);
                linkShape_.push_back(made.shape);
                ++created;
            }
    }
    if (anySplit) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < links_.size(); ++i)
            if (links_[i].receiver != kNoElement) {
                links_[kept] = links_[i];
                linkShape_[kept] = linkShape_[i];
                linkShare_[kept++] = linkShare_[i];
            }
        links_.resize(kept);
        linkShare_.resize(kept);
        linkShape_.resize(kept);
        patchRowsCurrent_ = false;
        leafRowsCurrent_ = false;
    }
    for (const std::size_t rays : raysPerThread_) rays_ += rays;
    if (anySplit || receiverLinkBegin_.size() != tree_.size() + 1) indexLinksByReceiver();
    return created;
}

void HierarchicalSolver::gather() {
    // By receiver (the links grouped by indexLinksByReceiver): each element's sums in link order, the
    // same bit for bit however the chunks are scheduled. Per element, the irradiance over each of its
    // four children-to-be (ReceiverShape.h); the element's mean is their average.
    const std::size_t n = tree_.size();
    gatheredShape_.resize(hierarchical::kShapeValues * n);
    auto& own = tree_.gatheredIrradiance();
    own.resize(n);
    const auto& radiosity = tree_.radiosity();
    parallelChunks(n, threads_, 1024, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t e = from; e < to; ++e) {
            std::array<Rgb, hierarchical::kShapeValues> sum{Rgb(0.0), Rgb(0.0), Rgb(0.0), Rgb(0.0)};
            for (std::uint32_t k = receiverLinkBegin_[e]; k < receiverLinkBegin_[e + 1]; ++k) {
                const std::uint32_t i = receiverLinks_[k];
                const Rgb& b = radiosity[links_[i].source];
                for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += static_cast<double>(linkShape_[i][c]) * b;
            }
            std::copy(sum.begin(), sum.end(), gatheredShape_.begin() + static_cast<std::ptrdiff_t>(hierarchical::kShapeValues * e));
            own[e] = 0.25 * (sum[0] + sum[1] + sum[2] + sum[3]);
        }
    });
}

double HierarchicalSolver::pushPull() {
    const std::size_t n = tree_.size();
    auto& radiosity = tree_.radiosity();
    pushedIrradiance_.resize(n);
    patchIrradianceCurrent_ = false;
    lightNewElements();
    Rgb change(0.0), emitted(0.0);
    // Push: parents precede children, so one forward sweep hands every leaf its ancestors' irradiance,
    // each ancestor's over the part the leaf covers (ReceiverShape.h), in place in gatheredShape_.
    for (ElementIndex e = 0; e < n; ++e) {
        const ElementIndex parent = tree_.parent(e);
        Rgb* shape = gatheredShape_.data() + hierarchical::kShapeValues * e;
        if (parent != kNoElement)
            hierarchical::addChildShape(gatheredShape_.data() + hierarchical::kShapeValues * parent,
                                        tree_.polygon(parent).count == 4, e - tree_.firstChild(parent), shape);
        pushedIrradiance_[e] = 0.25 * (shape[0] + shape[1] + shape[2] + shape[3]);
        if (!tree_.isLeaf(e)) continue;
        const std::uint32_t s = tree_.surface(e);
        const Rgb& irradiance = leafRowsCurrent_ ? leafIrradiance_[e] : pushedIrradiance_[e];
        const Rgb source = elementSource(e);
        const Rgb updated = source + surfaceReflectance_[s] * irradiance;
        change += tree_.area(e) * glm::abs(updated - radiosity[e]);
        emitted += tree_.area(e) * source;
        radiosity[e] = updated;
    }
    // Pull: children follow parents, so a backward sweep averages finished children.
    for (ElementIndex e = static_cast<ElementIndex>(n); e-- > 0;) {
        if (tree_.isLeaf(e)) continue;
        const ElementIndex first = tree_.firstChild(e);
        Rgb sum(0.0);
        for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c) sum += tree_.area(c) * radiosity[c];
        radiosity[e] = sum / tree_.area(e);
    }
    double residual = 0;
    for (int band = 0; band < 3; ++band)
        if (emitted[band] > 0) residual = std::max(residual, change[band] / emitted[band]);
    return residual;
}

void HierarchicalSolver::setLeavesToEmission() {
    patchIrradianceCurrent_ = false;
    lightNewElements();
    auto& radiosity = tree_.radiosity();
    for (ElementIndex e = 0; e < tree_.size(); ++e) radiosity[e] = elementSource(e);
    std::fill(tree_.gatheredIrradiance().begin(), tree_.gatheredIrradiance().end(), Rgb(0.0));
}

void HierarchicalSolver::mapSolution(bool gathered) {
    // Both loops per patch on both cores: on one they were ~14 ms of the Cornell box's solve (a
    // locate per patch after each of ~12 refining steps, a row per patch after each later step).
    // After a refining step each patch descends from the element it had (the tree only grows below
    // it), instead of a locate from the roots.
    if (mappedTreeSize_ != tree_.size() || patchElement_.size() != patches_.size()) {
        const bool mapped = patchElement_.size() == patches_.size();
        patchElement_.resize(patches_.size());
        parallelChunks(patches_.size(), threads_, 256, [&](std::size_t from, std::size_t to, unsigned) {
            for (std::size_t i = from; i < to; ++i) {
                const PatchSample& patch = patches_[i];
                // The element about the patch's size holds the area-weighted mean of the leaves under it.
                patchElement_[i] = mapped && patchElement_[i] != kNoElement
                                       ? tree_.descend(patchElement_[i], patch.centroid, 0.5 * patch.area)
                                       : tree_.locate(patch.surface, patch.face, patch.centroid, 0.5 * patch.area);
            }
        });
        mappedTreeSize_ = tree_.size();
    }
    solution_.resize(patches_.size());
    const auto& radiosity = tree_.radiosity();
    if (gathered && !patchRowsCurrent_) buildPatchRows();
    gathered = gathered && patchRowsCurrent_;
    if (gathered) patchIrradiance_.resize(patches_.size());
    parallelChunks(patches_.size(), threads_, 256, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t i = from; i < to; ++i) {
            if (gathered) patchIrradiance_[i] = patchRowIrradiance(i);
            solution_[i] = gathered && patches_[i].polygon.count >= 3 ? gatheredRadiosity(i)
                                                                       : radiosity[patchElement_[i]] + patchDirectCorrection(i);
        }
    });
    patchIrradianceCurrent_ = gathered;
    afterSolutionMapped();
}

IterationStats HierarchicalSolver::step() {
    const auto start = std::chrono::steady_clock::now();
    IterationStats stats;
    stats.iteration = stats_.iteration + 1;
    // Refinement also stops once a sweep changes B by under kSettleResidual: BF refinement adds a few
    // links at every step while B grows, and a solve that reached its tolerance first never built the
    // rows, so its answer was the leaves' constants (the Cornell box at seeds 2-4: 0.9-1.2% mean,
    // 5-12% worst at the points, against 0.2% / 0.6% where it happened to settle).
    // Only a residual measured after refining with the current materials counts (a material change
    // leaves the last one stale). After the importance view changes, refinement runs until no links
    // are made: the importance moves then, not B.
    const bool quiet = settleOnResidual_ && refinedSinceChange_ && stats_.residual < kSettleResidual;
    stats.linksRefined = linksSettled_ || quiet ? 0 : refine();
    if (!linksSettled_ && !quiet) refinedSinceChange_ = true;
    // The rows cost a form factor per patch (and per leaf the patches do not resolve) and per link of
    // its chain: they are built once refinement has settled (a step that made no links), and until
    // then push-pull pushes each link's shape. Once
    // built, the links stay until a material or the view changes: the rows move B by up to 1% of the
    // emitted power, the oracle then asked for a few dozen links, which dropped the rows, and the
    // Cornell box's default solve to 1e-4 rebuilt them six times (9 s loaded instead of 1 s).
    const bool settled = stats.linksRefined == 0;
    if (settled && !leafRowsCurrent_ && tree_.leafCount() <= kMaxLeavesWithRows) {
        buildLeafRows();
        linksSettled_ = true;
    }
    if (leafRowsCurrent_) gatherLeafRows();
    gather();
    stats.residual = pushPull();
    afterGather();
    mapSolution(settled);
    stats.links = links_.size();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_ = stats;
    return stats;
}

void HierarchicalSolver::setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) {
    if (surface >= surfaceReflectance_.size())
        throw RadiantError({"", "set material"}, "surface " + std::to_string(surface) + " out of range (" +
                                                     std::to_string(surfaceReflectance_.size()) + " surfaces)");
    for (int band = 0; band < 3; ++band) {
        if (!(reflectance[band] >= 0 && reflectance[band] < 1))
            throw RadiantError({"", "set material"}, "reflectance " + std::to_string(reflectance[band]) +
                                                         " outside [0, 1) for surface " + std::to_string(surface));
        if (!(exitance.value()[band] >= 0))
            throw RadiantError({"", "set material"}, "exitance " + std::to_string(exitance.value()[band]) +
                                                         " W/m^2 is negative for surface " + std::to_string(surface));
    }
    surfaceReflectance_[surface] = reflectance;
    surfaceExitance_[surface] = exitance.value();
    linksSettled_ = false;
    refinedSinceChange_ = false;
}

void HierarchicalSolver::reset() {
    // The links and rows stay as they are, settled or not (Solver::reset keeps the form factors):
    // refining settled links again from B = E split elements the first solve had not, so a Reset
    // and a second run moved most patches (the Cornell box at 0.004 m^2: worst 2.4%, importance 13%).
    refinedSinceChange_ = false;
    setLeavesToEmission();
    stats_ = {};
    mapSolution(false);
}

std::size_t HierarchicalSolver::bytes() const {
    std::size_t perThread = 0;
    for (const auto& b : splitsPerThread_) perThread += b.capacity() * sizeof(Split);
    for (const auto& b : linksPerThread_) perThread += b.capacity() * sizeof(NewLink);
    perThread += produced_.capacity() * sizeof(NewLink);
    return tree_.bytes() + links_.capacity() * sizeof(Link) + linkShare_.capacity() * sizeof(float) + pushedIrradiance_.capacity() * sizeof(Rgb) +
           linkShape_.capacity() * sizeof(linkShape_[0]) + gatheredShape_.capacity() * sizeof(Rgb) +
           importance_.capacity() * sizeof(double) + patchElement_.capacity() * sizeof(ElementIndex) +
           patches_.capacity() * sizeof(PatchSample) + solution_.capacity() * sizeof(Rgb) + perThread +
           (receiverLinkBegin_.capacity() + receiverLinks_.capacity()) * sizeof(std::uint32_t) +
           patchRowBegin_.capacity() * sizeof(std::size_t) +
           patchRows_.capacity() * sizeof(GatherTerm) + occluderCorners_.capacity() * sizeof(glm::dvec3) +
           occluderBegin_.capacity() * sizeof(std::uint32_t) + occluderBox_.capacity() * sizeof(glm::dvec3) + linkShaft_.capacity() +
           leafPoints_.capacity() * sizeof(LeafPoint) + leafFromPatches_.capacity() +
           (patchIrradiance_.capacity() + patchPushed_.capacity()) * sizeof(Rgb) +
           sourceRules_.capacity() * sizeof(hierarchical::SourceRule);
}

std::size_t HierarchicalSolver::raysCast() const {
    return rays_;
}

HierarchicalSetup hierarchicalSetupForElements(const Scene& scene, std::size_t elements, SolverOptions base) {
    const double leafArea = 2 * scene.totalArea() / static_cast<double>(std::max<std::size_t>(elements, 1));
    // The oracle refines a link at a leaf's parent (area 4a) while rho B dF 4a > linkEpsilon x emitted
    // power, i.e. while the radiosity error it leaves exceeds linkEpsilon x power / 4a. linkEpsilon
    // proportional to a^(3/2) makes that tolerance proportional to the leaf's edge sqrt(a): the error
    // piecewise-constant leaves have anyway. The tolerance shrinks as elements are added, so the
    // solution improves with them (linkEpsilon proportional to a held it fixed: more leaves, same answer).
    base.linkEpsilon = kScaledLinkEpsilon * std::pow(leafArea / scene.totalArea(), 1.5);
    base.minElementArea = 0.25 * leafArea * (1 - 1e-9);  // one level below the target where the oracle insists
    return {base, HierarchicalRefinement{leafArea}};
}

std::unique_ptr<Solver> makeHierarchicalSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                               Progress* progress) {
    return std::make_unique<HierarchicalSolver>(scene, mesh, options, progress);
}

} // namespace radiant
