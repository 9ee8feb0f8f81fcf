#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

PatchPolygon PatchPolygon::from(std::span<const glm::dvec3> corners) {
    if (corners.size() != 3 && corners.size() != 4) {
        throw RadiantError({"", "patch polygon"},
                           "a patch has 3 or 4 corners, not " + std::to_string(corners.size()));
    }
    PatchPolygon polygon;
    polygon.count = static_cast<std::uint8_t>(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) polygon.vertices[i] = corners[i];

    // Newell's normal: robust for any planar polygon, its length is twice the area.
    glm::dvec3 newell(0.0);
    for (std::size_t i = 0; i < corners.size(); ++i)
        newell += glm::cross(corners[i], corners[(i + 1) % corners.size()]);
    const double twiceArea = glm::length(newell);
    polygon.area = 0.5 * twiceArea;
    if (twiceArea > 0) polygon.normal = newell / twiceArea;

    // Area-weighted centroid from the fan of triangles around corner 0 (the plain corner mean is
    // wrong for a trapezoid). Signed areas along the normal keep it right for any convex quad.
    if (corners.size() == 3 || twiceArea == 0) {
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& c : corners) sum += c;
        polygon.centroid = sum / static_cast<double>(corners.size());
    } else {
        const double a1 = glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), polygon.normal);
        const double a2 = glm::dot(glm::cross(corners[2] - corners[0], corners[3] - corners[0]), polygon.normal);
        const glm::dvec3 c1 = (corners[0] + corners[1] + corners[2]) / 3.0;
        const glm::dvec3 c2 = (corners[0] + corners[2] + corners[3]) / 3.0;
        polygon.centroid = (a1 * c1 + a2 * c2) / (a1 + a2);
    }
    return polygon;
}

PatchPolygon PatchMesh::polygon(std::size_t patch) const {
    const Patch& p = patches.at(patch);
    std::array<glm::dvec3, 4> corners{};
    for (std::size_t i = 0; i < p.cornerCount; ++i) corners[i] = vertices[p.corners[i]];
    return PatchPolygon::from(std::span<const glm::dvec3>(corners.data(), p.cornerCount));
}

double PatchMesh::totalArea() const {
    double sum = 0;
    for (const Patch& p : patches) sum += p.area;
    return sum;
}

} // namespace radiant
