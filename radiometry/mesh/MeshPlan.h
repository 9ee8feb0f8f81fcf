#pragma once
// How every face will be cut, decided before any patch is made: the welded corners of each surface,
// its faces split into convex triangles and quads ("pieces"), and one segment count per edge.
// meshScene() emits from a plan; estimatePatchCount() only counts it, so both agree exactly.
//
// Conformity comes from the constraints on the counts: a quad's opposite edges carry the same
// count (its n x m grid), a triangle's three edges the same count (its uniform n-subdivision), and
// an edge shared by two pieces is one edge. Equal-count constraints form equivalence classes of
// edges (union-find), and each class takes the largest count any of its pieces asks for.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant::detail {

/// A convex triangle or quad cut from a face (faces with more corners are fanned into quads).
struct Piece {
    std::uint32_t face = 0;
    std::uint8_t count = 0;                  ///< 3 or 4
    std::array<std::uint32_t, 4> corners{};  ///< welded corner ids within the surface, face order
    std::array<std::uint32_t, 4> edges{};    ///< edge i runs corners[i] -> corners[(i + 1) % count]
};

struct PlanEdge {
    std::uint32_t low = 0, high = 0;  ///< welded corner ids, low < high
};

struct SurfacePlan {
    std::vector<glm::dvec3> corners;  ///< welded face corners of this surface
    std::vector<Piece> pieces;
    std::vector<PlanEdge> edges;
    std::vector<std::uint32_t> edgeClass;     ///< edge -> its class
    std::vector<std::uint64_t> classSegments; ///< class -> segment count (>= 1)

    [[nodiscard]] std::uint64_t segments(std::uint32_t edge) const { return classSegments[edgeClass[edge]]; }
};

struct MeshPlan {
    std::vector<SurfacePlan> surfaces;
    double patchCount = 0;  ///< double: an absurd request must not overflow before it is refused
};

/// Builds the plan; throws RadiantError for a maximum patch area that is not positive and finite.
MeshPlan planMeshing(const Scene& scene, const MeshingOptions& options);

} // namespace radiant::detail
