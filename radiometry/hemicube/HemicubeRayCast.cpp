#include "radiometry/hemicube/HemicubeRayCast.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "radiometry/hemicube/HemicubeGather.h"
#include "radiometry/hemisphere/HemisphericalCoordinates.h"

namespace radiant {

std::vector<std::uint32_t> castHemicube(const HemicubeLayout& layout, const RayCaster& rays,
                                        const PatchLocator& patches, const glm::dvec3& x, const glm::dvec3& n) {
    const HemisphereFrame frame(n);
    // Lifted off its own face so the first hit is never the face the point lies on.
    const glm::dvec3 origin = x + frame.normal() * (1e-7 * std::max(1.0, glm::length(x)));
    std::vector<std::uint32_t> items(layout.pixelCount(), kHemicubeEmpty);
    for (int row = 0; row < layout.height(); ++row)
        for (int column = 0; column < layout.width(); ++column) {
            const glm::dvec3 direction = frame.toWorld(layout.pixelDirection(column, row));
            const std::optional<RayHit> hit = rays.intersect(origin, direction);
            if (!hit) continue;
            const std::size_t patch = patches.find(hit->surface, hit->face, hit->point);
            if (patch == PatchLocator::npos) continue;
            const bool back = glm::dot(hit->normal, direction) > 0;
            items[static_cast<std::size_t>(row) * static_cast<std::size_t>(layout.width()) +
                  static_cast<std::size_t>(column)] = encodeHemicubeItem(patch, back);
        }
    return items;
}

} // namespace radiant
