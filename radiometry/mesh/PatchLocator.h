#pragma once
// From a point on the scene to the patch holding it: picking and the probe turn a ray hit
// (surface, face, point) into a patch to read the radiosity of.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

class PatchLocator {
public:
    /// Indexes the patches of every face. Keeps a reference: the mesh must outlive the locator.
    explicit PatchLocator(const PatchMesh& mesh);

    /// The patch of the given surface and face that contains `point` (taken in the patch's plane).
    /// A point just outside every patch (rounding at a face's border) gets the nearest patch;
    /// npos when the face has no patches. Cost: linear in the face's patch count.
    [[nodiscard]] std::size_t find(std::uint32_t surface, std::uint32_t face, const glm::dvec3& point) const;

    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

private:
    struct Range {
        std::uint32_t first = 0, last = 0;  ///< [first, last)
    };
    const PatchMesh& mesh_;
    std::vector<std::vector<Range>> faceRanges_;  ///< [surface][face]
};

/// How far `point` lies outside the convex patch, measured in its plane: <= 0 inside, else the
/// largest distance beyond one of its edge lines (metres).
double distanceOutsidePatch(const PatchMesh& mesh, std::size_t patch, const glm::dvec3& point);

} // namespace radiant
