#include "radiometry/mesh/ElementTree.h"

#include <array>
#include <limits>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/mesh/ConvexFan.h"
#include "radiometry/mesh/MeshPlan.h"

namespace radiant {

PatchPolygon makeElementPolygon(std::span<const glm::dvec3> corners) {
    PatchPolygon polygon;
    polygon.count = static_cast<std::uint8_t>(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) polygon.vertices[i] = corners[i];
    // A fan from corner 0: exact for convex polygons, and the areas weight the centroid.
    glm::dvec3 normalSum(0.0), centroidSum(0.0);
    double areaSum = 0;
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        const glm::dvec3 twiceArea = glm::cross(corners[i] - corners[0], corners[i + 1] - corners[0]);
        const double a = 0.5 * glm::length(twiceArea);
        normalSum += twiceArea;
        centroidSum += a * (corners[0] + corners[i] + corners[i + 1]) / 3.0;
        areaSum += a;
    }
    polygon.area = areaSum;
    const double normalLength = glm::length(normalSum);
    if (normalLength > 0) polygon.normal = normalSum / normalLength;
    polygon.centroid = areaSum > 0 ? centroidSum / areaSum : corners[0];
    return polygon;
}

namespace {

/// True when `point` (in or near the polygon's plane) lies inside the convex polygon, with a
/// tolerance relative to the polygon's size so points on shared edges belong to both sides.
bool polygonContains(const PatchPolygon& polygon, const glm::dvec3& point) {
    const auto corners = polygon.corners();
    const double tolerance = 1e-9 * (polygon.area + 1e-300);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3& a = corners[i];
        const glm::dvec3& b = corners[(i + 1) % corners.size()];
        if (glm::dot(glm::cross(b - a, point - a), polygon.normal) < -tolerance) return false;
    }
    return true;
}

} // namespace

ElementTree::ElementTree(const Scene& scene, const detail::ContactPolygons* cuts) {
    // Cuts of another scene (a mesh passed with the wrong scene) are not used.
    if (cuts && cuts->size() != scene.surfaces.size()) cuts = nullptr;
    for (std::size_t s = 0; cuts && s < scene.surfaces.size(); ++s)
        if ((*cuts)[s].size() != scene.surfaces[s].faces.size()) cuts = nullptr;
    const detail::ContactPolygons cutHere = cuts ? detail::ContactPolygons{} : detail::cutAlongContacts(scene);
    const detail::ContactPolygons& contacts = cuts ? *cuts : cutHere;
    const double weld = detail::weldTolerance(scene);
    surfaceFirstFace_.push_back(0);
    faceFirstRoot_.push_back(0);
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        for (std::size_t f = 0; f < surface.faces.size(); ++f) {
            const auto& v = surface.faces[f].vertices;
            if (v.size() < 3)
                throw RadiantError({scene.name, "surface '" + surface.name + "', face " + std::to_string(f)},
                                   "a face needs at least 3 corners, it has " + std::to_string(v.size()));
            // A face cut along contacts (ContactCuts.h) gets roots from its cut polygons, so no element
            // straddles the footprint of what stands on it.
            // Larger polygons are split into the mesher's pieces (ConvexFan.h), so every patch lies in
            // one root and reads it through locate().
            const auto addRoots = [&](const std::vector<glm::dvec3>& polygon) {
                std::vector<glm::dvec3> corners;
                for (const glm::dvec3& c : polygon)
                    if (corners.empty() || glm::distance(corners.back(), c) > weld) corners.push_back(c);
                while (corners.size() > 1 && glm::distance(corners.front(), corners.back()) <= weld) corners.pop_back();
                if (corners.size() < 3) corners = polygon;  // degenerate: makeElementPolygon says what is wrong
                if (corners.size() <= 4) {
                    roots_.push_back(append(makeElementPolygon(corners), Node{kNoElement, kNoElement, s, 0}));
                    return;
                }
                detail::forEachFanPiece(corners.size(), [&](std::size_t first, std::size_t count) {
                    std::array<glm::dvec3, 4> piece{};
                    piece[0] = corners[0];
                    for (std::size_t j = 1; j < count; ++j) piece[j] = corners[first + j - 1];
                    roots_.push_back(append(makeElementPolygon(std::span<const glm::dvec3>(piece.data(), count)),
                                            Node{kNoElement, kNoElement, s, 0}));
                });
            };
            if (contacts[s][f].empty()) {
                addRoots(v);
            } else {
                for (const auto& polygon : contacts[s][f]) addRoots(polygon);
            }
            faceFirstRoot_.push_back(static_cast<std::uint32_t>(roots_.size()));
        }
        surfaceFirstFace_.push_back(static_cast<std::uint32_t>(faceFirstRoot_.size() - 1));
    }
    rootCount_ = roots_.size();
}

ElementIndex ElementTree::append(const PatchPolygon& polygon, const Node& node) {
    if (polygons_.size() >= kNoElement)
        throw BudgetError({}, "the element tree is full (" + std::to_string(polygons_.size()) + " elements)");
    const auto index = static_cast<ElementIndex>(polygons_.size());
    polygons_.push_back(polygon);
    nodes_.push_back(node);
    radiosity_.push_back(node.parent == kNoElement ? Rgb(0.0) : radiosity_[node.parent]);
    gathered_.emplace_back(0.0);
    return index;
}

std::array<PatchPolygon, 4> splitElementPolygon(const PatchPolygon& parent) {
    const auto& v = parent.vertices;
    const auto mid = [](const glm::dvec3& a, const glm::dvec3& b) { return 0.5 * (a + b); };
    const auto make = [&](std::initializer_list<glm::dvec3> corners) {
        PatchPolygon polygon = makeElementPolygon({corners.begin(), corners.size()});
        polygon.normal = parent.normal;  // children of a planar element share its plane
        return polygon;
    };
    if (parent.count == 4) {
        // Bilinear split: edge midpoints and the parametric centre (the mean of the corners).
        const glm::dvec3 m01 = mid(v[0], v[1]), m12 = mid(v[1], v[2]), m23 = mid(v[2], v[3]), m30 = mid(v[3], v[0]);
        const glm::dvec3 centre = 0.25 * (v[0] + v[1] + v[2] + v[3]);
        return {make({v[0], m01, centre, m30}), make({m01, v[1], m12, centre}), make({centre, m12, v[2], m23}),
                make({m30, centre, m23, v[3]})};
    }
    const glm::dvec3 m01 = mid(v[0], v[1]), m12 = mid(v[1], v[2]), m20 = mid(v[2], v[0]);
    // The medial triangle (last) keeps the parent's winding.
    return {make({v[0], m01, m20}), make({m01, v[1], m12}), make({m20, m12, v[2]}), make({m01, m12, m20})};
}

ElementIndex ElementTree::subdivide(ElementIndex e) {
    if (nodes_[e].firstChild != kNoElement) return nodes_[e].firstChild;
    const std::array<PatchPolygon, 4> children = splitElementPolygon(polygons_[e]);
    const Node child{e, kNoElement, nodes_[e].surface, nodes_[e].depth + 1};
    const ElementIndex first = append(children[0], child);
    for (std::size_t c = 1; c < children.size(); ++c) append(children[c], child);
    nodes_[e].firstChild = first;
    return first;
}

std::vector<ElementIndex> ElementTree::leaves() const {
    std::vector<ElementIndex> result;
    result.reserve(leafCount());
    for (ElementIndex e = 0; e < size(); ++e)
        if (isLeaf(e)) result.push_back(e);
    return result;
}

ElementIndex ElementTree::locate(std::uint32_t surfaceIndex, std::uint32_t face, const glm::dvec3& point,
                                 double minArea) const {
    if (surfaceIndex + 1 >= surfaceFirstFace_.size()) return kNoElement;
    const std::uint32_t globalFace = surfaceFirstFace_[surfaceIndex] + face;
    if (globalFace >= surfaceFirstFace_[surfaceIndex + 1]) return kNoElement;
    ElementIndex found = kNoElement;
    double nearestRoot = std::numeric_limits<double>::max();
    for (std::uint32_t r = faceFirstRoot_[globalFace]; r < faceFirstRoot_[globalFace + 1]; ++r) {
        const PatchPolygon& polygon = polygons_[roots_[r]];
        if (polygonContains(polygon, point)) {
            found = roots_[r];
            break;
        }
        const glm::dvec3 d = polygon.centroid - point;
        if (glm::dot(d, d) < nearestRoot) {
            nearestRoot = glm::dot(d, d);
            found = roots_[r];
        }
    }
    if (found == kNoElement) return kNoElement;
    return descend(found, point, minArea);
}

ElementIndex ElementTree::descend(ElementIndex from, const glm::dvec3& point, double minArea) const {
    ElementIndex found = from;
    while (!isLeaf(found) && polygons_[found].area * 0.25 >= minArea * (1 - 1e-9)) {
        const ElementIndex first = nodes_[found].firstChild;
        // Points on a shared edge are in two children; round-off may put one in none: then the
        // child whose centroid is nearest is the right one.
        ElementIndex next = kNoElement;
        double nearest = std::numeric_limits<double>::max();
        for (ElementIndex c = first; c < first + kChildCount; ++c) {
            if (polygonContains(polygons_[c], point)) {
                next = c;
                break;
            }
            const glm::dvec3 d = polygons_[c].centroid - point;
            if (glm::dot(d, d) < nearest) {
                nearest = glm::dot(d, d);
                next = c;
            }
        }
        found = next;
    }
    return found;
}

bool ElementTree::contains(ElementIndex e, const glm::dvec3& point) const {
    return polygonContains(polygons_[e], point);
}

std::size_t ElementTree::bytes() const {
    return nodes_.capacity() * sizeof(Node) + polygons_.capacity() * sizeof(PatchPolygon) +
           radiosity_.capacity() * sizeof(Rgb) + gathered_.capacity() * sizeof(Rgb) +
           roots_.capacity() * sizeof(ElementIndex) + faceFirstRoot_.capacity() * sizeof(std::uint32_t) +
           surfaceFirstFace_.capacity() * sizeof(std::uint32_t);
}

} // namespace radiant
