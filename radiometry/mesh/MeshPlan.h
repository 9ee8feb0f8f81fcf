#pragma once
// How every face will be cut, decided before any patch is made: the welded corners of each surface,
// its faces split into convex triangles and quads ("pieces"), and one segment count per edge.
// meshScene() emits from a plan; estimatePatchCount() only counts it, so both agree exactly.
//
// Conformity comes from the constraints on the counts: a quad's opposite edges carry the same
// count (its n x m grid) and an edge shared by two pieces is one edge. Equal-count constraints form
// equivalence classes of edges (union-find), and each class takes the largest count any of its
// pieces asks for. A triangle's three edges stay free: one with equal counts is cut uniformly, one
// with unequal counts is triangulated between its edges' vertices or, when larger than a patch,
// gets a uniform core stitched to its edges (TriangleCut). Tying a triangle's
// edges together would chain every triangle of a tessellated surface into one class, so that its
// largest triangle set the count of all: a 3,072-triangle rounded cube became 27,162 patches.
//
// A piece along a contact on its open side (the floor before a block's side: ContactCuts.h gives
// the contacts' segments) asks for cells of MeshingOptions::besideContactAreaShare of the area
// there, where the lamp's penumbra and the contact's corner make the radiosity vary fastest. Its
// counts pass along its rows and columns like any other (a quad's opposite edges are one class), so
// in the square-walled box the refinement spreads over most of the floor: 195 more patches in the
// Cornell box at 13 cm^2. A local refinement would need T-junctions or transition triangles.
#include <array>
#include <cstdint>
#include <memory>
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
    /// A triangle of at most two patches' area (it asks for two segments on its longest edge at
    /// most): unequal edge counts then need no vertex inside it.
    bool fitsTwoPatches = true;
    /// Cut from a face along contacts (ContactCuts.h): only such a piece can lie under what stands on
    /// its face, so only these are asked whether they are covered.
    bool contactCut = false;
    bool covered = false;  ///< set by meshScene() (coveredPiece), not by planning
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
    /// Patches meshScene() cuts the piece into (double: see MeshPlan::patchCount).
    [[nodiscard]] double patchCount(const Piece& piece) const;
};

/// How meshScene() cuts a triangle piece with edge counts a, b, c.
enum class TriangleCut {
    Lattice,  ///< equal counts: the uniform lattice, a^2 similar triangles
    Zipper,   ///< unequal counts on a triangle that fits two patches: its edge vertices alone,
              ///< joined across, a + b + c - 2 triangles
    Core,     ///< unequal counts on a larger triangle: a lattice core stitched to the edges
};
TriangleCut triangleCut(const Piece& piece, std::uint64_t a, std::uint64_t b, std::uint64_t c);

/// Segments of a triangle's lattice: the largest of its edge counts, but at least 3 for a Core cut
/// (whose core is then at least the centroid, to which the edges are stitched).
std::uint64_t triangleCoreSegments(std::uint64_t a, std::uint64_t b, std::uint64_t c);

struct MeshPlan {
    std::vector<SurfacePlan> surfaces;
    double patchCount = 0;  ///< double: an absurd request must not overflow before it is refused
    std::shared_ptr<const ContactPolygons> contacts;  ///< the faces cut along contacts, per surface and face
};

/// Corners closer than this are one (m): a billionth of the scene's size, so float-rounded copies of
/// a corner merge and distinct corners never do. The element tree drops repeated corners by it too.
double weldTolerance(const Scene& scene);

/// The diagonal of the box round every face corner, m (1 for a scene without corners).
double sceneDiagonal(const Scene& scene);

/// Builds the plan; throws RadiantError for a maximum patch area that is not positive and finite.
MeshPlan planMeshing(const Scene& scene, const MeshingOptions& options);

} // namespace radiant::detail
