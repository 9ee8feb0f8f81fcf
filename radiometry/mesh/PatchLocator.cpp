#include "radiometry/mesh/PatchLocator.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace radiant {

PatchLocator::PatchLocator(const PatchMesh& mesh) : mesh_(mesh) {
    // meshScene emits the patches of a face together and faces in order, so a range suffices.
    for (std::uint32_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        if (faceRanges_.size() <= patch.surface) faceRanges_.resize(patch.surface + 1);
        auto& faces = faceRanges_[patch.surface];
        if (faces.size() <= patch.face) faces.resize(patch.face + 1, Range{p, p});
        Range& range = faces[patch.face];
        if (range.first == range.last) range.first = p;
        range.last = p + 1;
    }
}

std::size_t PatchLocator::find(std::uint32_t surface, std::uint32_t face, const glm::dvec3& point) const {
    if (surface >= faceRanges_.size() || face >= faceRanges_[surface].size()) return npos;
    const Range range = faceRanges_[surface][face];
    std::size_t best = npos;
    double bestOutside = std::numeric_limits<double>::infinity();
    for (std::uint32_t p = range.first; p < range.last; ++p) {
        const double outside = distanceOutsidePatch(mesh_, p, point);
        if (outside <= 0) return p;
        if (outside < bestOutside) {
            bestOutside = outside;
            best = p;
        }
    }
    return best;
}

double distanceOutsidePatch(const PatchMesh& mesh, std::size_t patch, const glm::dvec3& point) {
    const Patch& p = mesh.patches[patch];
    double outside = std::numeric_limits<double>::lowest();
    for (std::size_t i = 0; i < p.cornerCount; ++i) {
        const glm::dvec3& a = mesh.vertices[p.corners[i]];
        const glm::dvec3& b = mesh.vertices[p.corners[(i + 1) % p.cornerCount]];
        // The inward direction of edge a -> b in the patch's plane (corners are counter-clockwise
        // about the normal).
        const glm::dvec3 inward = glm::cross(p.normal, b - a);
        const double length = glm::length(inward);
        if (length == 0) continue;
        outside = std::max(outside, -glm::dot(point - a, inward) / length);
    }
    return outside;
}

} // namespace radiant
