#include "radiometry/probe/ChordError.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

namespace radiant {
namespace {

using Corner = std::array<double, 3>;
using Edge = std::pair<Corner, Corner>;  ///< corners in lexicographic order: one key for both windings

Corner corner(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

glm::dvec3 centroid(const Face& face) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& v : face.vertices) sum += v;
    return sum / static_cast<double>(face.vertices.size());
}

/// The radius of the circle through the face's corners where the face is inscribed in a sphere (the
/// circle through its first three), the gap being widest at that circle's centre; for a face that is
/// not, no more than the largest distance from its centroid to a corner.
double cornerCircleRadius(const Face& face) {
    const glm::dvec3 centre = centroid(face);
    double reach = 0;
    for (const glm::dvec3& v : face.vertices) reach = std::max(reach, glm::length(v - centre));
    const glm::dvec3 a = face.vertices[1] - face.vertices[0], b = face.vertices[2] - face.vertices[0];
    const double twiceArea = glm::length(glm::cross(a, b));
    if (!(twiceArea > 0)) return reach;
    return std::min(reach, glm::length(a) * glm::length(b) * glm::length(a - b) / (2 * twiceArea));
}

std::vector<double> surfaceChordErrors(const Surface& surface) {
    const std::size_t count = surface.faces.size();
    std::map<Edge, std::vector<std::size_t>> facesOfEdge;
    for (std::size_t f = 0; f < count; ++f) {
        const std::vector<glm::dvec3>& v = surface.faces[f].vertices;
        for (std::size_t i = 0; i < v.size(); ++i) {
            Corner a = corner(v[i]), b = corner(v[(i + 1) % v.size()]);
            if (b < a) std::swap(a, b);
            facesOfEdge[{a, b}].push_back(f);
        }
    }
    std::vector<int> curvedEdges(count, 0);
    std::vector<double> curvature(count, 0.0);  // the largest across a curved edge, 1/m
    for (const auto& [edge, faces] : facesOfEdge) {
        if (faces.size() != 2) continue;  // a boundary, or a non-manifold edge: no neighbour to follow
        const Face& a = surface.faces[faces[0]];
        const Face& b = surface.faces[faces[1]];
        const double turn = std::acos(std::clamp(glm::dot(a.normal, b.normal), -1.0, 1.0));
        const double distance = glm::length(centroid(a) - centroid(b));
        // Below ~1e-6 rad the faces are one plane up to float rounding: nothing to snap onto.
        if (!(turn > 1e-6) || turn > kCurvedTurnRadians || !(distance > 0)) continue;
        for (const std::size_t f : faces) {
            ++curvedEdges[f];
            curvature[f] = std::max(curvature[f], turn / distance);
        }
    }
    std::vector<double> errors(count, 0.0);
    for (std::size_t f = 0; f < count; ++f)
        if (curvedEdges[f] >= 2) {
            const double r = cornerCircleRadius(surface.faces[f]);
            errors[f] = curvature[f] * r * r / 2;
        }
    return errors;
}

} // namespace

std::vector<std::vector<double>> tessellationChordErrors(const Scene& scene) {
    std::vector<std::vector<double>> errors;
    errors.reserve(scene.surfaces.size());
    for (const Surface& surface : scene.surfaces) errors.push_back(surfaceChordErrors(surface));
    return errors;
}

} // namespace radiant
