#pragma once
// The scene's surfaces cut into patches: the unknowns of the radiosity system. Within a surface the
// mesh is conforming (neighbouring patches share vertices, no T-junctions), so radiosity can be
// interpolated across patch edges; vertices are not shared across surfaces, where radiosity jumps.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/common/Progress.h"
#include "radiometry/scene/Scene.h"

namespace radiant {

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

struct Patch {
    std::uint32_t surface = 0;  ///< index into Scene::surfaces
    std::uint32_t face = 0;     ///< index into that surface's faces
    std::array<std::uint32_t, 4> corners{};  ///< into PatchMesh::vertices; corners[3] unused for triangles
    std::uint8_t cornerCount = 0;
    glm::dvec3 centroid{0.0};
    glm::dvec3 normal{0, 0, 1};
    double area = 0;  ///< m^2
};

struct MeshingOptions {
    double maxPatchArea = 0.01;          ///< m^2; every patch is at most this large (and not much smaller),
                                         ///< up to a relative 4e-6 that absorbs float-rounded dimensions
    std::size_t patchBudget = 2'000'000; ///< refuse (BudgetError, with the numbers) above this
};

struct PatchMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<Patch> patches;
    /// Patches of surface s are [surfaceFirstPatch[s], surfaceFirstPatch[s + 1]); size surfaces + 1.
    std::vector<std::uint32_t> surfaceFirstPatch;

    [[nodiscard]] std::size_t size() const { return patches.size(); }
    [[nodiscard]] PatchPolygon polygon(std::size_t patch) const;
    [[nodiscard]] double totalArea() const;
};

/// Cuts every face of the scene into patches no larger than options.maxPatchArea: quads where the
/// face is a quad, triangles otherwise. Throws BudgetError before allocating when the estimated
/// patch count exceeds options.patchBudget. Reports progress and honours cancellation when given.
PatchMesh meshScene(const Scene& scene, const MeshingOptions& options, Progress* progress = nullptr);

/// Estimated patch count of meshScene(scene, options), cheap, for budgets and UI hints.
std::size_t estimatePatchCount(const Scene& scene, const MeshingOptions& options);

} // namespace radiant
