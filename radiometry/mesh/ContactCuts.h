#pragma once
// Contact-aware meshing (issue 14): a face is cut along the lines where other faces stand on it (the
// footprint of a block on a floor), so that no patch or element straddles a contact line. A patch
// half under a block is dark on its covered half and, averaged, reads as its open share of the right
// radiosity; everything that sees the floor then sees it too dark (docs/ARCHITECTURE.md, "Accuracy",
// has the Cornell box's numbers with and without the cut).
//
// A contact is an edge of a face not parallel to this one, lying in this face's plane (within a
// tolerance relative to the scene's size) with a part inside the face, whose face stands on this
// face's front (a lid lying face down, a double-sided twin or a wall below the floor is none); or the
// line where a face passes through this face's plane, with a part inside it (a box sunk into a
// floor cuts the floor along its footprint, and the floor cuts the box's sides where they cross). The
// contact's whole line cuts, in turn, every convex piece of the faces of the surface in that plane:
// a line leaves two convex pieces of a convex one, and a line that crosses an edge two pieces share
// cuts both. Cutting only the pieces the contact segment crosses was tried: the cuts then ended on
// the footprint's lines, whose pieces took those ends as corners and were fanned from their centre,
// and the thin triangles running away from the block's foot averaged its shadow with the open floor
// (converged Gauss-Seidel at the Cornell short block's side over it 2.35% bright at 0.001 m^2 against
// the path tracer; 0.71% with whole lines). Where a cut ends on an edge of the surface out of the
// plane, that edge takes the cut's end as a corner, and its polygon, now with a corner on a straight
// side, is fanned into triangles from its centre: no T-junction within a surface. A floor with many
// things on it is crossed by all their lines, up to a budget of pieces. Corners within the snap
// distance of a line count as on it, so a cut close to a corner or along an edge goes through it and
// leaves no sliver.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant {
class RayCaster;
}

namespace radiant::detail {

/// For every face of every surface, the strictly convex polygons it is cut into ([surface][face]);
/// an empty list for a face no contact cuts (use the face itself). Used by the mesher (MeshPlan) and
/// the hierarchical element tree (ElementTree) alike, so both see the same footprints.
using ContactPolygons = std::vector<std::vector<std::vector<std::vector<glm::dvec3>>>>;

/// A contact lying in a face's plane: the segment where something stands on it, and the side of the
/// segment light reaches (away from what stands there).
struct ContactSegment {
    glm::dvec3 from{0.0}, to{0.0};
    glm::dvec3 open{0.0};  ///< unit, in the plane, perpendicular to the segment
    double snap = 0;       ///< m: a corner this close to the segment's line lies on it
};
/// [surface][face]: the contacts that cut each face (a face takes those of its plane's other faces).
using ContactSegments = std::vector<std::vector<std::vector<ContactSegment>>>;

/// A surface whose cut would take more than kMostContactPieces pieces is left uncut, with one line
/// in `warnings` (when given) naming it. `segments`, when given, receives the contacts that cut
/// (none for a surface left uncut).
ContactPolygons cutAlongContacts(const Scene& scene, std::vector<std::string>* warnings = nullptr,
                                 ContactSegments* segments = nullptr);

/// True when a piece of a face (a convex polygon with its front normal) is covered: seen from a point
/// `offset` m in front of its centre, no ray of a fixed set over the hemisphere (the normal and four
/// rings of eight, 5 to 70 degrees above the plane) meets the front of a face first, and at least one
/// meets the back of one. The floor under a block (the block's sides and top seen from behind) and a
/// box's side sunk below the floor (the floor seen from below, the void beyond) are covered; the floor
/// beside the block, which sees the block's front, is not, nor is a face with nothing in front of it.
/// Covered patches see nothing the solvers can light and come out near their own exitance (0 on a
/// floor): the radiosity drawn leaves them out of its vertex averages (OpenFirstMean.h).
/// Traced through `rays`, a RayCaster of the scene whose piece this is (its BVH: brute force over
/// every face cost the mesher 33 rays x faces per piece).
bool coveredPiece(const RayCaster& rays, std::span<const glm::dvec3> polygon, const glm::dvec3& normal, double offset);

/// How far in front of a piece's centre coveredPiece() looks from, relative to the scene's diagonal:
/// ten times kContactPlaneTolerance, so clear of a block standing a tolerance above the floor.
inline constexpr double kCoveredOffset = 1e-4;

/// Relative to the scene's diagonal: how far from a face's plane a contact edge may lie, and how
/// close to a cut line a corner is taken as on it.
inline constexpr double kContactPlaneTolerance = 1e-5;
inline constexpr double kContactSnap = 5e-4;
/// A contact edge's own snap is at most this share of its length (below kContactSnap x the diagonal).
inline constexpr double kContactSnapOfEdge = 0.05;
/// Two cut lines this parallel (cosine) through the same point are one.
inline constexpr double kSameDirection = 1 - 1e-9;
/// Most pieces one surface's contacts may cut it into; the T-junction pass after the cut is quadratic in them.
inline constexpr std::size_t kMostContactPieces = 4096;

} // namespace radiant::detail
