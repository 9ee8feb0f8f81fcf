// Importance-driven radiosity: B. Smits, J. Arvo, D. Salesin, "An importance-driven radiosity
// algorithm", SIGGRAPH 1992. The hierarchy, links and push-pull are Hanrahan et al.'s
// (HierarchicalSolver); this file adds the camera's importance and its adjoint transport.
#include "radiometry/solver/ImportanceSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/solver/HierarchicalParallel.h"
#include "radiometry/solver/SolverFactories.h"

namespace radiant {

ImportanceSolver::ImportanceSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                   Progress* progress)
    : HierarchicalSolver(scene, mesh, options, progress), sceneArea_(scene.totalArea()) {
    // homeView casts rays: only when needed, and through the scene's caster when there is one.
    castEyeRays(scene, options.view ? *options.view : homeView(scene, rayCaster()));
    setImportanceToEmission();
    afterSolutionMapped();
}

bool ImportanceSolver::setView(const Scene& scene, const View& view) {
    castEyeRays(scene, view);
    // Hand the new hits down the existing tree, parents before children (a child's index is always
    // above its parent's), as onSubdivided did when each was split.
    const ElementTree& tree = elements();
    for (ElementIndex e = 0; e < tree.size(); ++e)
        if (!tree.isLeaf(e)) distributeHits(e);
    // Importance restarts from the new emission; radiosity and links stay, and the next steps
    // refine where the new view needs it and gather again.
    setImportanceToEmission();
    resumeRefinement();
    afterSolutionMapped();
    return true;
}

namespace {

std::string vectorText(const glm::dvec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

} // namespace

void ImportanceSolver::castEyeRays(const Scene& scene, const View& view) {
    const glm::dvec3 forwardRaw = view.target - view.eye;
    const glm::dvec3 rightRaw = glm::cross(forwardRaw, view.up);
    if (!(glm::length(forwardRaw) > 0) || !(glm::length(rightRaw) > 0) || !(view.verticalFov > 0) ||
        !(view.verticalFov < 3.1) || !(view.aspect > 0))
        throw RadiantError({scene.name, "importance camera"},
                           "degenerate camera: the eye must differ from the target, up must not be parallel to the "
                           "view direction, the vertical field of view (" + std::to_string(view.verticalFov) +
                               " rad) must lie in (0, 3.1) and the aspect (" + std::to_string(view.aspect) +
                               ") be positive");
    const glm::dvec3 forward = glm::normalize(forwardRaw);
    const glm::dvec3 right = glm::normalize(rightRaw);
    const glm::dvec3 up = glm::cross(right, forward);
    const double halfHeight = std::tan(0.5 * view.verticalFov);
    const double halfWidth = halfHeight * view.aspect;

    std::unique_ptr<RayCaster> ownCaster;
    const RayCaster* caster = rayCaster();
    if (!caster) {
        ownCaster = std::make_unique<RayCaster>(scene);
        caster = ownCaster.get();
    }

    const ElementTree& tree = elements();
    constexpr int n = kImageResolution;
    std::vector<std::vector<std::pair<ElementIndex, glm::dvec3>>> hitsPerThread(threads());
    parallelChunks(static_cast<std::size_t>(n), threads(), 8, [&](std::size_t from, std::size_t to, unsigned thread) {
        for (std::size_t row = from; row < to; ++row)
            for (int column = 0; column < n; ++column) {
                // Pixel centres of an n x n grid over the image: each ray stands for an equal share of it.
                const double u = (2 * (column + 0.5) / n - 1) * halfWidth;
                const double v = (1 - 2 * (static_cast<double>(row) + 0.5) / n) * halfHeight;
                const glm::dvec3 direction = forward + u * right + v * up;
                const auto hit = caster->intersect(view.eye, direction);
                if (!hit || glm::dot(hit->normal, direction) >= 0) continue;  // nothing, or a face's back
                const ElementIndex root =
                    tree.locate(hit->surface, hit->face, hit->point, std::numeric_limits<double>::infinity());
                if (root != kNoElement) hitsPerThread[thread].emplace_back(root, hit->point);
            }
    });
    std::vector<std::pair<ElementIndex, glm::dvec3>> all;
    for (auto& buffer : hitsPerThread) all.insert(all.end(), buffer.begin(), buffer.end());
    // No front face in view: every importance would be zero, the refinement threshold zero, and the
    // solve would stay on the roots without saying why. Refuse the view instead (and keep the last).
    if (all.empty())
        throw RadiantError({scene.name, "importance camera"},
                           "the view from " + vectorText(view.eye) + " towards " + vectorText(view.target) +
                               " sees no surface's front (every eye ray misses or hits the back of a face), so "
                               "importance is zero everywhere and nothing would be refined: aim the camera at the "
                               "scene's lit side (from inside a closed room)");
    std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    rayCount_ = static_cast<std::size_t>(n) * n;
    hits_.clear();
    hitBegin_.assign(tree.size(), 0);
    hitEnd_.assign(tree.size(), 0);
    for (std::size_t i = 0; i < all.size(); ++i) {
        const ElementIndex e = all[i].first;
        if (i == 0 || all[i - 1].first != e) hitBegin_[e] = static_cast<std::uint32_t>(i);
        hitEnd_[e] = static_cast<std::uint32_t>(i + 1);
        hits_.push_back(all[i].second);
    }
}

double ImportanceSolver::elementEmittedImportance(ElementIndex e) const {
    const double share = static_cast<double>(hitEnd_[e] - hitBegin_[e]) / static_cast<double>(rayCount_);
    return share / elements().area(e);
}

void ImportanceSolver::setImportanceToEmission() {
    const ElementTree& tree = elements();
    importance_.resize(tree.size());
    for (ElementIndex e = 0; e < tree.size(); ++e) importance_[e] = elementEmittedImportance(e);
}

void ImportanceSolver::onSubdivided(ElementIndex parent) {
    const ElementTree& tree = elements();
    hitBegin_.resize(tree.size());
    hitEnd_.resize(tree.size());
    importance_.resize(tree.size());
    distributeHits(parent);
    const ElementIndex first = tree.firstChild(parent);
    for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c) importance_[c] = importance_[parent];
}

void ImportanceSolver::distributeHits(ElementIndex parent) {
    // Hand the parent's eye-ray hits to the children that contain them (a point on a shared edge
    // goes to the first).
    const ElementTree& tree = elements();
    const ElementIndex first = tree.firstChild(parent);
    auto begin = hits_.begin() + hitBegin_[parent];
    const auto end = hits_.begin() + hitEnd_[parent];
    for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c) {
        const bool last = c + 1 == first + ElementTree::kChildCount;
        const auto split =
            last ? end : std::partition(begin, end, [&](const glm::dvec3& p) { return tree.contains(c, p); });
        hitBegin_[c] = static_cast<std::uint32_t>(begin - hits_.begin());
        hitEnd_[c] = static_cast<std::uint32_t>(split - hits_.begin());
        begin = split;
    }
}

void ImportanceSolver::afterGather() {
    const ElementTree& tree = elements();
    const std::size_t n = tree.size();
    // Importance leaving an element: its reflectance (mean over bands: importance is one number)
    // times its importance.
    sourceImportance_.resize(n);
    for (ElementIndex e = 0; e < n; ++e) sourceImportance_[e] = meanReflectance(e) * importance_[e];
    gatherPerThread_.resize(threads());
    for (auto& buffer : gatherPerThread_) buffer.assign(n, 0.0);
    const auto links = this->links();
    // One block per accumulator, as in the radiosity gather: deterministic sums.
    const std::size_t block = std::max<std::size_t>((links.size() + threads() - 1) / threads(), 1);
    parallelChunks(links.size(), threads(), block, [&](std::size_t from, std::size_t to, unsigned) {
        double* gathered = gatherPerThread_[from / block].data();
        for (std::size_t i = from; i < to; ++i)
            gathered[links[i].receiver] += static_cast<double>(links[i].formFactor) * sourceImportance_[links[i].source];
    });
    for (std::size_t t = 1; t < gatherPerThread_.size(); ++t)
        for (std::size_t e = 0; e < n; ++e) gatherPerThread_[0][e] += gatherPerThread_[t][e];
    const std::vector<double>& gathered = gatherPerThread_[0];

    // Push-pull, as for radiosity: pushed down, emitted importance added at the leaves, pulled up.
    pushedImportance_.resize(n);
    for (ElementIndex e = 0; e < n; ++e) {
        const ElementIndex parent = tree.parent(e);
        pushedImportance_[e] = gathered[e] + (parent == kNoElement ? 0.0 : pushedImportance_[parent]);
        if (tree.isLeaf(e)) importance_[e] = elementEmittedImportance(e) + pushedImportance_[e];
    }
    for (ElementIndex e = static_cast<ElementIndex>(n); e-- > 0;) {
        if (tree.isLeaf(e)) continue;
        const ElementIndex first = tree.firstChild(e);
        double sum = 0;
        for (ElementIndex c = first; c < first + ElementTree::kChildCount; ++c) sum += tree.area(c) * importance_[c];
        importance_[e] = sum / tree.area(e);
    }
}

void ImportanceSolver::afterSolutionMapped() {
    const auto patchElements = this->patchElements();
    patchImportance_.resize(patchElements.size());
    patchEmittedImportance_.resize(patchElements.size());
    if (importance_.size() != elements().size()) return;  // still being constructed
    for (std::size_t i = 0; i < patchElements.size(); ++i) {
        patchImportance_[i] = importance_[patchElements[i]];
        patchEmittedImportance_[i] = elementEmittedImportance(patchElements[i]);
    }
}

double ImportanceSolver::refinementThreshold() const {
    // Hierarchical radiosity's threshold (a fraction of the emitted power) times the scene's mean
    // emitted importance: where importance is average, both methods refine alike.
    const double hitShare = static_cast<double>(hits_.size()) / static_cast<double>(rayCount_);
    return HierarchicalSolver::refinementThreshold() * hitShare / sceneArea_;
}

Rgb ImportanceSolver::imageResponse() const {
    const ElementTree& tree = elements();
    Rgb sum(0.0);
    for (ElementIndex e = 0; e < tree.size(); ++e)
        if (tree.isLeaf(e)) sum += tree.area(e) * elementEmittedImportance(e) * tree.radiosity()[e];
    return sum;
}

Rgb ImportanceSolver::adjointResponse() const {
    const ElementTree& tree = elements();
    Rgb sum(0.0);
    for (ElementIndex e = 0; e < tree.size(); ++e)
        if (tree.isLeaf(e)) sum += tree.area(e) * importance_[e] * elementSource(e);
    return sum;
}

void ImportanceSolver::reset() {
    HierarchicalSolver::reset();
    setImportanceToEmission();
    afterSolutionMapped();
}

std::unique_ptr<Solver> makeImportanceSolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                             Progress* progress) {
    return std::make_unique<ImportanceSolver>(scene, mesh, options, progress);
}

} // namespace radiant
