// The punctual lights' source term for hierarchical and importance-driven radiosity: elements refine
// finer than patches, so each element gets its own direct irradiance H (DirectLighting.h), the mean
// over its polygon, and B = E + rho (H + gathered) at the leaves. Elements only ever append to the
// tree, so H is computed once per element, when push-pull first meets it.
#include "radiometry/probe/PolygonSamples.h"
#include "radiometry/solver/HierarchicalParallel.h"
#include "radiometry/solver/HierarchicalSolver.h"

namespace radiant {

Rgb HierarchicalSolver::elementSource(ElementIndex e) const {
    const std::uint32_t s = tree_.surface(e);
    if (e >= elementDirect_.size()) return surfaceExitance_[s];  // no lights
    return surfaceExitance_[s] + surfaceReflectance_[s] * elementDirect_[e];
}

Rgb HierarchicalSolver::patchDirectCorrection(std::size_t patch) const {
    // Refinement follows the links' error, not the lights': an element may be far larger than the
    // patches that show it, and its mean H would draw a point light's pool of light as blocks.
    if (patch >= patchDirect_.size()) return Rgb(0.0);
    const ElementIndex element = patchElement_[patch];
    if (element >= elementDirect_.size()) return Rgb(0.0);
    return surfaceReflectance_[tree_.surface(element)] * (patchDirect_[patch] - elementDirect_[element]);
}

void HierarchicalSolver::lightNewElements() {
    if (!lighting_) return;
    const std::size_t first = elementDirect_.size();
    elementDirect_.resize(tree_.size());
    parallelChunks(tree_.size() - first, threads(), 64, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t i = first + from; i < first + to; ++i)
            elementDirect_[i] = lighting_->meanOver(tree_.polygon(static_cast<ElementIndex>(i)), DirectLighting::kSamplesPerSide,
                                                    mixBits(options_.seed ^ mixBits(i)))
                                    .value();
    });
    if (patchDirect_.size() == patches_.size()) return;
    patchDirect_.resize(patches_.size());
    parallelChunks(patches_.size(), threads(), 64, [&](std::size_t from, std::size_t to, unsigned) {
        for (std::size_t i = from; i < to; ++i) {
            const PatchSample& patch = patches_[i];
            patchDirect_[i] = patch.polygon.count >= 3
                                  ? lighting_->meanOver(patch.polygon, DirectLighting::kSamplesPerSide, mixBits(options_.seed ^ ~mixBits(i))).value()
                                  : Rgb(0.0);
        }
    });
}

} // namespace radiant
