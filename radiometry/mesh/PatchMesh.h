#pragma once
// The scene's surfaces cut into patches: the unknowns of the radiosity system. Within a surface the
// mesh is conforming (neighbouring patches share vertices, no T-junctions), so radiosity can be
// interpolated across patch edges; vertices are not shared across surfaces, where radiosity jumps.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "radiometry/common/Progress.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/scene/Scene.h"

namespace radiant {

class RayCaster;

/// A planar convex triangle or quad with its derived geometry, in metres. Patches and the
/// hierarchical solver's elements both use it.
struct PatchPolygon {
    std::array<glm::dvec3, 4> vertices{};
    std::uint8_t count = 0;  ///< 3 or 4
    glm::dvec3 normal{0, 0, 1};
    glm::dvec3 centroid{0.0};
    double area = 0;

    [[nodiscard]] std::span<const glm::dvec3> corners() const { return {vertices.data(), count}; }
    /// Builds the polygon and derives normal, area-weighted centroid and area.
    static PatchPolygon from(std::span<const glm::dvec3> corners);
};

/// Faces are flat only to their input's precision: glTF stores float positions (a 0.07 m facet of
/// a sphere 0.7 m from the origin is flat to 1e-7 of its size), and TriangleMerging joins triangles
/// whose normals agree to 1e-5 rad. What lies within this fraction of a polygon's size (the square
/// root of its area) of its plane lies in that plane. Above all a double-sided face's twin, the same
/// corners reversed: taken as a hair in front, it covered the whole hemisphere of the points a
/// rounding error below it (F = 0.42 on average between a sphere's facets and their twins, which lit
/// the closed sphere's inside and made its outside 14% too bright).
inline constexpr double kRelativePlanarity = 1e-4;

/// How far from the plane of a (or b) the pair's corners may lie and still be in it, m.
[[nodiscard]] inline double planarityTolerance(const PatchPolygon& a, const PatchPolygon& b) {
    return kRelativePlanarity * std::sqrt(std::max(a.area, b.area));
}

/// True when `point` lies in front of the polygon's plane by more than the polygon's planarity: only
/// then can it receive light from the polygon's front (a point in the plane sees it edge-on).
[[nodiscard]] inline bool inFrontOfPlane(const PatchPolygon& polygon, const glm::dvec3& point) {
    return glm::dot(polygon.normal, point - polygon.centroid) > kRelativePlanarity * std::sqrt(polygon.area);
}

/// The largest distance from the centroid to a corner, m: a sphere of this radius round the centroid
/// holds the polygon.
[[nodiscard]] inline double circumradius(const PatchPolygon& polygon) {
    double radius = 0;
    for (const glm::dvec3& corner : polygon.corners()) radius = std::max(radius, glm::length(corner - polygon.centroid));
    return radius;
}

struct Patch {
    std::uint32_t surface = 0;  ///< index into Scene::surfaces
    std::uint32_t face = 0;     ///< index into that surface's faces
    std::array<std::uint32_t, 4> corners{};  ///< into PatchMesh::vertices; corners[3] unused for triangles
    std::uint8_t cornerCount = 0;
    glm::dvec3 centroid{0.0};
    glm::dvec3 normal{0, 0, 1};
    double area = 0;  ///< m^2
    /// Lies under something standing on its face (the floor under a block) or behind a face that cuts
    /// it (a box's side below the floor): detail::coveredPiece. It sees only backs, so its radiosity is
    /// near its own exitance; the radiosity drawn leaves it out of the vertex averages of open patches.
    bool covered = false;
};

struct MeshingOptions {
    double maxPatchArea = 0.01;          ///< m^2; every patch is at most this large (and not much smaller),
                                         ///< up to a relative 4e-6 that absorbs float-rounded dimensions
    std::size_t patchBudget = 2'000'000; ///< refuse (BudgetError, with the numbers) above this
    /// A piece of a face cut along a contact (ContactCuts.h) that lies along it on the open side (the
    /// floor before a block's side) asks for patches of this share of maxPatchArea: there the lamp's
    /// penumbra and the contact's corner make the radiosity vary fastest. Conformity carries the finer
    /// counts along the piece's rows and columns (MeshPlan.h). 1: no refinement.
    double besideContactAreaShare = 0.5;
};

struct PatchMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<Patch> patches;
    /// Patches of surface s are [surfaceFirstPatch[s], surfaceFirstPatch[s + 1]); size surfaces + 1.
    std::vector<std::uint32_t> surfaceFirstPatch;
    /// The scene's faces cut along contacts (ContactCuts.h), as the patches tile them; the hierarchical
    /// solver's element tree takes its roots from the same polygons instead of cutting again. Null in
    /// a mesh not made by meshScene.
    std::shared_ptr<const detail::ContactPolygons> contactCuts;

    [[nodiscard]] std::size_t size() const { return patches.size(); }
    [[nodiscard]] PatchPolygon polygon(std::size_t patch) const;
    [[nodiscard]] double totalArea() const;
};

/// Cuts every face of the scene into patches no larger than options.maxPatchArea: quads where the
/// face is a quad, triangles otherwise. Throws BudgetError before allocating when the estimated
/// patch count exceeds options.patchBudget. Reports progress and honours cancellation when given.
/// `rays`, a RayCaster of this scene when the caller holds one (the lab's solver thread shares one per
/// scene), traces the covered test of the pieces cut along contacts (detail::coveredPiece); without
/// it one is built, only for a scene that has such pieces.
PatchMesh meshScene(const Scene& scene, const MeshingOptions& options, Progress* progress = nullptr,
                    const RayCaster* rays = nullptr);

/// Estimated patch count of meshScene(scene, options), cheap, for budgets and UI hints.
std::size_t estimatePatchCount(const Scene& scene, const MeshingOptions& options);

} // namespace radiant
