#pragma once
// Flat pictures of the hemisphere over a point, as a lecture draws them. Each maps the unit disk to
// directions; the item a view pixel shows is looked up in the hemicube (HemicubeLayout::pixelIndexOf).
//
//   Nusselt analog (Nusselt 1928): project the unit hemisphere straight down onto its base disk.
//     A direction (theta, phi) lands at radius sin(theta); a patch of solid angle d omega covers
//     cos(theta) d omega of the disk, so the fraction of the disk's area pi a surface covers is its
//     form factor. Inverse: (u, v) -> (u, v, sqrt(1 - u^2 - v^2)).
//   Equidistant fisheye: radius theta / (pi / 2); angles from the normal read off linearly.
//   Equisolid (equal-area) fisheye: radius sqrt(2) sin(theta / 2); area on the disk is proportional
//     to solid angle, so the fraction of the disk a surface covers is Omega / (2 pi).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "radiometry/hemicube/HemicubeLayout.h"

namespace radiant {

enum class HemisphereProjection { Nusselt, Equidistant, Equisolid };

/// "Nusselt analog", "equidistant fisheye", "equisolid fisheye".
const char* projectionName(HemisphereProjection projection);

/// The local direction (z = normal, unit) shown at disk point (u, v); nullopt outside the unit disk.
std::optional<glm::dvec3> directionAtDiskPoint(HemisphereProjection projection, glm::dvec2 diskPoint);
/// Where a local direction with z >= 0 appears on the unit disk.
glm::dvec2 diskPointOfDirection(HemisphereProjection projection, const glm::dvec3& localDirection);

/// For a size x size image of the disk (rows top first): the hemicube atlas index each pixel shows,
/// or -1 outside the disk. The image is what the point would photograph looking out along its
/// normal: image up is the local horizontal direction at azimuth `upAzimuth` (radians from the
/// tangent), image right is normal x up. Computed once per (layout, projection, size, up).
class HemisphereViewMap {
public:
    HemisphereViewMap(const HemicubeLayout& layout, HemisphereProjection projection, int size,
                      double upAzimuth = 1.5707963267948966);
    /// The local direction (unit, z = normal) image point (x right, y up, both in [-1, 1]) shows.
    [[nodiscard]] std::optional<glm::dvec3> directionAt(glm::dvec2 imagePoint) const;
    [[nodiscard]] int size() const { return size_; }
    [[nodiscard]] HemisphereProjection projection() const { return projection_; }
    [[nodiscard]] const std::vector<std::int64_t>& atlasIndex() const { return atlasIndex_; }
    /// Pixels inside the disk.
    [[nodiscard]] std::size_t diskPixels() const { return diskPixels_; }

private:
    HemisphereProjection projection_;
    int size_;
    glm::dvec2 up_{0, 1}, right_{-1, 0};  ///< image axes in the local tangent plane
    std::vector<std::int64_t> atlasIndex_;
    std::size_t diskPixels_ = 0;
};

/// Fraction of the disk's pixels that show `predicate(item)`: in the Nusselt view, a form factor.
template <class Predicate>
double diskCoverage(const HemisphereViewMap& map, std::span<const std::uint32_t> items, Predicate predicate) {
    std::size_t covered = 0;
    for (const std::int64_t index : map.atlasIndex())
        if (index >= 0 && predicate(items[static_cast<std::size_t>(index)])) ++covered;
    return map.diskPixels() == 0 ? 0.0 : static_cast<double>(covered) / static_cast<double>(map.diskPixels());
}

} // namespace radiant
