#pragma once
// The hierarchical solver's elements: one quadtree per scene face, subdivided lazily where the
// refinement oracle asks for more detail (Hanrahan, Salzman, Aupperle 1991). A quad splits into four
// bilinear children, a triangle into four midpoint children; a face with more than four corners is
// fanned into triangle roots first.
//
// Nodes live in flat arrays addressed by 32-bit indices (no pointers, no per-node allocation), and
// children are always appended after their parent, so a forward sweep over the indices visits
// parents before children (push) and a backward sweep children before parents (pull).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

using ElementIndex = std::uint32_t;
inline constexpr ElementIndex kNoElement = 0xFFFF'FFFFu;

class ElementTree {
public:
    /// One root per triangle or quad face, a fan of triangle roots per larger convex face. `cuts`: the
    /// scene's faces cut along contacts (PatchMesh::contactCuts, the same polygons its patches tile), or
    /// null to cut them here (~2 ms of the Cornell box's 2.3 ms).
    explicit ElementTree(const Scene& scene, const detail::ContactPolygons* cuts = nullptr);

    [[nodiscard]] std::size_t size() const { return polygons_.size(); }
    [[nodiscard]] std::span<const ElementIndex> roots() const { return {roots_.data(), rootCount_}; }

    [[nodiscard]] const PatchPolygon& polygon(ElementIndex e) const { return polygons_[e]; }
    [[nodiscard]] double area(ElementIndex e) const { return polygons_[e].area; }
    [[nodiscard]] std::uint32_t surface(ElementIndex e) const { return nodes_[e].surface; }
    [[nodiscard]] ElementIndex parent(ElementIndex e) const { return nodes_[e].parent; }
    /// The four children are firstChild .. firstChild + 3; kNoElement for a leaf.
    [[nodiscard]] ElementIndex firstChild(ElementIndex e) const { return nodes_[e].firstChild; }
    [[nodiscard]] bool isLeaf(ElementIndex e) const { return nodes_[e].firstChild == kNoElement; }
    [[nodiscard]] std::uint32_t depth(ElementIndex e) const { return nodes_[e].depth; }
    static constexpr std::uint32_t kChildCount = 4;

    /// Splits a leaf into its four children (their radiosity starts as the parent's, their gathered
    /// irradiance at zero) and returns the first; returns the existing first child otherwise.
    /// Not thread-safe: the solver subdivides between its parallel phases.
    ElementIndex subdivide(ElementIndex e);

    [[nodiscard]] std::vector<ElementIndex> leaves() const;
    /// Each split turns one leaf into four.
    [[nodiscard]] std::size_t leafCount() const { return rootCount_ + 3 * interiorCount(); }

    /// The deepest element of face `face` of surface `surfaceIndex` containing `point` (which lies
    /// on the face), descending no further than elements of area >= minArea. A point off the face
    /// goes to the nearest root of that face; kNoElement only for a face that does not exist.
    [[nodiscard]] ElementIndex locate(std::uint32_t surfaceIndex, std::uint32_t face, const glm::dvec3& point,
                                      double minArea = 0) const;
    /// locate's descent from `from` (an element holding `point`, as locate found it): the element
    /// locate returns now, after the tree has grown below `from`. Splitting leaves never changes the
    /// path to an existing element, so a map of points to elements kept up to date this way equals
    /// locate's from the roots.
    [[nodiscard]] ElementIndex descend(ElementIndex from, const glm::dvec3& point, double minArea = 0) const;

    /// True when `point` (on or near the element's plane) lies inside the element; points on an edge
    /// count as inside both neighbours.
    [[nodiscard]] bool contains(ElementIndex e, const glm::dvec3& point) const;

    /// Per-element radiosity B (W/m^2 per band): at a leaf its own, at an interior node the
    /// area-weighted mean of its children (the "pull" of push-pull).
    [[nodiscard]] std::vector<Rgb>& radiosity() { return radiosity_; }
    [[nodiscard]] const std::vector<Rgb>& radiosity() const { return radiosity_; }
    /// Per-element irradiance gathered over the element's own links (W/m^2 per band), before the
    /// ancestors' share is pushed down.
    [[nodiscard]] std::vector<Rgb>& gatheredIrradiance() { return gathered_; }
    [[nodiscard]] const std::vector<Rgb>& gatheredIrradiance() const { return gathered_; }

    /// Heap bytes held by the tree (capacity, not size: what the process really pays).
    [[nodiscard]] std::size_t bytes() const;

private:
    struct Node {
        ElementIndex parent = kNoElement;
        ElementIndex firstChild = kNoElement;
        std::uint32_t surface = 0;
        std::uint32_t depth = 0;
    };

    [[nodiscard]] std::size_t interiorCount() const { return (size() - rootCount_) / kChildCount; }
    ElementIndex append(const PatchPolygon& polygon, const Node& node);

    std::vector<Node> nodes_;
    std::vector<PatchPolygon> polygons_;
    std::vector<Rgb> radiosity_;
    std::vector<Rgb> gathered_;
    std::vector<ElementIndex> roots_;
    std::size_t rootCount_ = 0;
    /// Roots of global face g (faces numbered surface by surface) are
    /// roots_[faceFirstRoot_[g] .. faceFirstRoot_[g + 1]).
    std::vector<std::uint32_t> faceFirstRoot_;
    std::vector<std::uint32_t> surfaceFirstFace_;
};

/// Polygon geometry (normal, centroid, area) from corners, without depending on the mesher.
PatchPolygon makeElementPolygon(std::span<const glm::dvec3> corners);

/// The four children of a triangle (midpoint split) or quad (bilinear split), in the parent's plane
/// and winding: what ElementTree::subdivide creates.
std::array<PatchPolygon, 4> splitElementPolygon(const PatchPolygon& parent);

} // namespace radiant
