#include "radiometry/hemicube/HemisphereProjection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace radiant {

const char* projectionName(HemisphereProjection projection) {
    switch (projection) {
    case HemisphereProjection::Nusselt: return "Nusselt analog";
    case HemisphereProjection::Equidistant: return "equidistant fisheye";
    case HemisphereProjection::Equisolid: return "equisolid fisheye";
    }
    return "?";
}

std::optional<glm::dvec3> directionAtDiskPoint(HemisphereProjection projection, glm::dvec2 p) {
    const double radius = std::hypot(p.x, p.y);
    if (radius > 1.0) return std::nullopt;
    double theta = 0;
    switch (projection) {
    case HemisphereProjection::Nusselt: return glm::dvec3(p.x, p.y, std::sqrt(std::max(0.0, 1.0 - radius * radius)));
    case HemisphereProjection::Equidistant: theta = radius * std::numbers::pi / 2; break;
    case HemisphereProjection::Equisolid: theta = 2.0 * std::asin(radius / std::numbers::sqrt2); break;
    }
    if (radius == 0) return glm::dvec3(0, 0, 1);
    const double s = std::sin(theta) / radius;
    return glm::dvec3(p.x * s, p.y * s, std::cos(theta));
}

glm::dvec2 diskPointOfDirection(HemisphereProjection projection, const glm::dvec3& d) {
    const double horizontal = std::hypot(d.x, d.y);
    const double theta = std::atan2(horizontal, d.z);
    double radius = 0;
    switch (projection) {
    case HemisphereProjection::Nusselt: radius = std::sin(theta); break;
    case HemisphereProjection::Equidistant: radius = theta / (std::numbers::pi / 2); break;
    case HemisphereProjection::Equisolid: radius = std::numbers::sqrt2 * std::sin(theta / 2); break;
    }
    if (horizontal == 0) return {0, 0};
    return {d.x / horizontal * radius, d.y / horizontal * radius};
}

HemisphereViewMap::HemisphereViewMap(const HemicubeLayout& layout, HemisphereProjection projection, int size,
                                     double upAzimuth)
    : projection_(projection), size_(size),
      up_(std::cos(upAzimuth), std::sin(upAzimuth)), right_(-std::sin(upAzimuth), std::cos(upAzimuth)),
      atlasIndex_(static_cast<std::size_t>(size) * static_cast<std::size_t>(size), -1) {
    for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
            const glm::dvec2 p{(column + 0.5) / size * 2.0 - 1.0, 1.0 - (row + 0.5) / size * 2.0};
            const std::optional<glm::dvec3> d = directionAt(p);
            if (!d) continue;
            atlasIndex_[static_cast<std::size_t>(row) * static_cast<std::size_t>(size) +
                        static_cast<std::size_t>(column)] = static_cast<std::int64_t>(layout.pixelIndexOf(*d));
            ++diskPixels_;
        }
}

std::optional<glm::dvec3> HemisphereViewMap::directionAt(glm::dvec2 imagePoint) const {
    // Image right = normal x up (a camera looking out along the normal), so the picture is not mirrored.
    return directionAtDiskPoint(projection_, imagePoint.x * right_ + imagePoint.y * up_);
}

} // namespace radiant
