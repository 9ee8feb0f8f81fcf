// Meshing: every face into a conforming grid of patches, quads on quads and triangles on triangles.
// The segment counts come from detail::planMeshing (see MeshPlan.h); this file only emits them.
// Vertices on an edge are made once and shared by both pieces that meet there, so the mesh has no
// T-junctions within a surface (Baum, Mann, Smith and Winget, "Making radiosity usable: automatic
// preprocessing and meshing techniques for the generation of accurate radiosity solutions",
// SIGGRAPH 1991, on why T-junctions show as cracks and shading seams).
#include <array>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/common/NumberText.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/mesh/MeshPlan.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant {
namespace {

using detail::Piece;
using detail::SurfacePlan;

/// Emits one surface's vertices and patches into the mesh.
class SurfaceEmitter {
public:
    SurfaceEmitter(const SurfacePlan& plan, std::uint32_t surface, PatchMesh& mesh)
        : plan_(plan), surface_(surface), mesh_(mesh), cornerBase_(static_cast<std::uint32_t>(mesh.vertices.size())) {
        mesh_.vertices.insert(mesh_.vertices.end(), plan.corners.begin(), plan.corners.end());
        // Interior vertices of every edge, once, ordered from its low corner to its high corner.
        edgeFirstVertex_.reserve(plan.edges.size());
        for (std::uint32_t e = 0; e < plan.edges.size(); ++e) {
            edgeFirstVertex_.push_back(static_cast<std::uint32_t>(mesh_.vertices.size()));
            const std::uint64_t n = plan.segments(e);
            const glm::dvec3 a = plan.corners[plan.edges[e].low], b = plan.corners[plan.edges[e].high];
            for (std::uint64_t k = 1; k < n; ++k) mesh_.vertices.push_back(lerp(a, b, k, n));
        }
    }

    void emit(const Piece& piece) {
        if (piece.count == 4)
            emitQuad(piece);
        else
            emitTriangle(piece);
    }

private:
    static glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, std::uint64_t k, std::uint64_t n) {
        const double t = static_cast<double>(k) / static_cast<double>(n);
        return a + t * (b - a);
    }

    /// The vertex k segments along the piece's edge `side` from its start corner.
    std::uint32_t onEdge(const Piece& piece, std::size_t side, std::uint64_t k) const {
        const std::uint32_t edge = piece.edges[side];
        const std::uint64_t n = plan_.segments(edge);
        const bool forward = plan_.edges[edge].low == piece.corners[side];
        const std::uint64_t fromLow = forward ? k : n - k;
        if (fromLow == 0) return cornerBase_ + plan_.edges[edge].low;
        if (fromLow == n) return cornerBase_ + plan_.edges[edge].high;
        return edgeFirstVertex_[edge] + static_cast<std::uint32_t>(fromLow - 1);
    }

    glm::dvec3 corner(const Piece& piece, std::size_t i) const { return plan_.corners[piece.corners[i]]; }

    void addPatch(const Piece& piece, std::initializer_list<std::uint32_t> corners) {
        Patch patch;
        patch.surface = surface_;
        patch.face = piece.face;
        patch.cornerCount = static_cast<std::uint8_t>(corners.size());
        std::array<glm::dvec3, 4> points{};
        std::size_t i = 0;
        for (std::uint32_t c : corners) {
            patch.corners[i] = c;
            points[i++] = mesh_.vertices[c];
        }
        const PatchPolygon polygon = PatchPolygon::from(std::span<const glm::dvec3>(points.data(), i));
        patch.centroid = polygon.centroid;
        patch.normal = polygon.normal;
        patch.area = polygon.area;
        patch.covered = piece.covered;
        mesh_.patches.push_back(patch);
    }

    // Grid (i, j), i along edge 0 (corner 0 -> 1), j along edge 3 reversed (corner 0 -> 3).
    void emitQuad(const Piece& piece) {
        const std::uint64_t nu = plan_.segments(piece.edges[0]), nv = plan_.segments(piece.edges[1]);
        const auto interiorBase = static_cast<std::uint32_t>(mesh_.vertices.size());
        const glm::dvec3 p0 = corner(piece, 0), p1 = corner(piece, 1), p2 = corner(piece, 2), p3 = corner(piece, 3);
        for (std::uint64_t j = 1; j < nv; ++j) {
            const glm::dvec3 left = lerp(p0, p3, j, nv), right = lerp(p1, p2, j, nv);
            for (std::uint64_t i = 1; i < nu; ++i) mesh_.vertices.push_back(lerp(left, right, i, nu));
        }
        const auto at = [&](std::uint64_t i, std::uint64_t j) -> std::uint32_t {
            if (j == 0) return onEdge(piece, 0, i);
            if (i == nu) return onEdge(piece, 1, j);
            if (j == nv) return onEdge(piece, 2, nu - i);
            if (i == 0) return onEdge(piece, 3, nv - j);
            return interiorBase + static_cast<std::uint32_t>((j - 1) * (nu - 1) + (i - 1));
        };
        for (std::uint64_t j = 0; j < nv; ++j)
            for (std::uint64_t i = 0; i < nu; ++i)
                addPatch(piece, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }

    // Barycentric lattice (i, j): point p0 + i/n (p1 - p0) + j/n (p2 - p0), i + j <= n. Equal edge
    // counts make the plain lattice; unequal ones keep its interior (a core lattice of n - 3
    // segments on the vertices with i, j, n - i - j >= 1) and stitch the core's sides to the edges.
    void emitTriangle(const Piece& piece) {
        const std::array<std::uint64_t, 3> edge{plan_.segments(piece.edges[0]), plan_.segments(piece.edges[1]),
                                                plan_.segments(piece.edges[2])};
        const detail::TriangleCut cut = detail::triangleCut(piece, edge[0], edge[1], edge[2]);
        if (cut == detail::TriangleCut::Zipper) {
            emitZipper(piece);
            return;
        }
        const std::uint64_t n = detail::triangleCoreSegments(edge[0], edge[1], edge[2]);
        const bool uniform = cut == detail::TriangleCut::Lattice;
        const glm::dvec3 p0 = corner(piece, 0), p1 = corner(piece, 1), p2 = corner(piece, 2);
        const auto interiorBase = static_cast<std::uint32_t>(mesh_.vertices.size());
        // Interior rows j = 1..n-2 hold i = 1..n-1-j; rowStart[j] is the first of row j.
        std::vector<std::uint32_t> rowStart(n + 1, 0);
        std::uint32_t next = interiorBase;
        for (std::uint64_t j = 1; j + 1 < n; ++j) {
            rowStart[j] = next;
            for (std::uint64_t i = 1; i + j < n; ++i, ++next) {
                const double u = static_cast<double>(i) / static_cast<double>(n);
                const double v = static_cast<double>(j) / static_cast<double>(n);
                mesh_.vertices.push_back(p0 + u * (p1 - p0) + v * (p2 - p0));
            }
        }
        const auto interior = [&](std::uint64_t i, std::uint64_t j) { return rowStart[j] + static_cast<std::uint32_t>(i - 1); };
        if (!uniform) {
            for (std::size_t side = 0; side < 3; ++side) stitch(piece, side, n, interior);
            emitLattice(piece, n - 3, [&](std::uint64_t i, std::uint64_t j) { return interior(i + 1, j + 1); });
            return;
        }
        emitLattice(piece, n, [&](std::uint64_t i, std::uint64_t j) -> std::uint32_t {
            if (j == 0) return onEdge(piece, 0, i);
            if (i + j == n) return onEdge(piece, 1, j);
            if (i == 0) return onEdge(piece, 2, n - j);
            return interior(i, j);
        });
    }

    /// A triangle that fits two patches and whose edges carry unequal counts: the convex polygon
    /// of its edge vertices, triangulated without a vertex inside. With corners A, B, C named so
    /// that C -> A is the edge with the most segments (at least 2), the chain A -> B -> C is zipped
    /// against the chain A -> C (that edge reversed), each step taking the shorter new diagonal.
    /// Neither chain steps onto C before the other is next to it, so a step's three vertices never
    /// lie on one edge and no triangle is degenerate. Each triangle has its base on an edge segment
    /// and its apex on another edge: a base on C -> A, on an edge cut at least twice, or a whole
    /// edge (the first and last triangles, whose apex is one segment of C -> A from its end) bounds
    /// it by half the piece's area, so it stays within the requested area.
    void emitZipper(const Piece& piece) {
        std::size_t most = 0;
        for (std::size_t side = 1; side < 3; ++side)
            if (plan_.segments(piece.edges[side]) > plan_.segments(piece.edges[most])) most = side;
        const std::size_t ab = (most + 1) % 3, bc = (most + 2) % 3, ca = most;
        std::vector<std::uint32_t> right, left;
        for (const std::size_t side : {ab, bc}) {
            const std::uint64_t n = plan_.segments(piece.edges[side]);
            for (std::uint64_t k = 0; k < n; ++k) right.push_back(onEdge(piece, side, k));
        }
        right.push_back(onEdge(piece, ca, 0));
        const std::uint64_t nca = plan_.segments(piece.edges[ca]);
        for (std::uint64_t k = 0; k <= nca; ++k) left.push_back(onEdge(piece, ca, nca - k));
        const auto length = [&](std::uint32_t a, std::uint32_t b) { return glm::distance(mesh_.vertices[a], mesh_.vertices[b]); };
        const std::size_t lastRight = right.size() - 1, lastLeft = left.size() - 1;  // both C
        addPatch(piece, {right[0], right[1], left[1]});
        std::size_t i = 1, j = 1;
        while (i + 1 < lastRight || j + 1 < lastLeft) {
            const bool canRight = i + 1 < lastRight, canLeft = j + 1 < lastLeft;
            const bool stepRight = canRight && (!canLeft || length(right[i + 1], left[j]) <= length(right[i], left[j + 1]));
            if (stepRight) {
                addPatch(piece, {right[i], right[i + 1], left[j]});
                ++i;
            } else {
                addPatch(piece, {right[i], left[j + 1], left[j]});
                ++j;
            }
        }
        if (i < lastRight && j < lastLeft) addPatch(piece, {right[i], right[lastRight], left[j]});
    }

    /// The n^2 triangles of a lattice of n segments, row by row, up(i, j) then down(i, j): the
    /// order ProgressiveShooters recognises.
    template <class Vertex>
    void emitLattice(const Piece& piece, std::uint64_t n, const Vertex& at) {
        for (std::uint64_t j = 0; j < n; ++j)
            for (std::uint64_t i = 0; i + j < n; ++i) {
                addPatch(piece, {at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j + 1 < n) addPatch(piece, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
    }

    /// Triangulates the band between edge `side` (its own count of segments) and the parallel side
    /// of the core, one lattice step inside, advancing along whichever polyline is behind. Each
    /// triangle has one side on a polyline and its apex on the other, one step away, so none
    /// exceeds the piece's area over (its own count x n): under the requested area, as every edge
    /// carries at least the piece's own count. The inner vertex comes first, so no band triangle
    /// passes ProgressiveShooters' lattice test.
    template <class Interior>
    void stitch(const Piece& piece, std::size_t side, std::uint64_t n, const Interior& interior) {
        const std::uint64_t outerCount = plan_.segments(piece.edges[side]);
        std::vector<std::uint32_t> inner;  // the core's side, from the side's start corner to its end
        for (std::uint64_t t = 1; t + 1 < n; ++t) {
            if (side == 0) inner.push_back(interior(t, 1));
            else if (side == 1) inner.push_back(interior(n - 1 - t, t));
            else inner.push_back(interior(1, n - 1 - t));
        }
        const glm::dvec3 start = corner(piece, side), along = corner(piece, (side + 1) % 3) - start;
        const auto progress = [&](std::uint32_t vertex) { return glm::dot(mesh_.vertices[vertex] - start, along); };
        std::uint64_t i = 0;
        std::size_t j = 0;
        while (i < outerCount || j + 1 < inner.size()) {
            const bool outerNext = j + 1 >= inner.size() ||
                                   (i < outerCount && progress(onEdge(piece, side, i + 1)) <= progress(inner[j + 1]));
            if (outerNext) {
                addPatch(piece, {inner[j], onEdge(piece, side, i), onEdge(piece, side, i + 1)});
                ++i;
            } else {
                addPatch(piece, {inner[j], onEdge(piece, side, i), inner[j + 1]});
                ++j;
            }
        }
    }

    const SurfacePlan& plan_;
    std::uint32_t surface_;
    PatchMesh& mesh_;
    std::uint32_t cornerBase_;
    std::vector<std::uint32_t> edgeFirstVertex_;
};

std::size_t saturatingCount(double count) {
    constexpr auto most = static_cast<double>(std::numeric_limits<std::size_t>::max() / 2);
    return count >= most ? static_cast<std::size_t>(most) : static_cast<std::size_t>(count);
}

} // namespace

std::size_t estimatePatchCount(const Scene& scene, const MeshingOptions& options) {
    return saturatingCount(detail::planMeshing(scene, options).patchCount);
}

PatchMesh meshScene(const Scene& scene, const MeshingOptions& options, Progress* progress, const RayCaster* rays) {
    detail::MeshPlan plan = detail::planMeshing(scene, options);
    if (plan.patchCount > static_cast<double>(options.patchBudget)) {
        throw BudgetError({scene.name, "meshing"},
                          "meshing at " + threeDigits(options.maxPatchArea) + " m^2 would make " +
                              threeDigits(plan.patchCount) + " patches; the budget is " +
                              threeDigits(static_cast<double>(options.patchBudget)));
    }
    // Vertex indices are 32-bit: refuse what they cannot address, whatever the budget says.
    if (plan.patchCount > 1e9) {
        throw BudgetError({scene.name, "meshing"}, "meshing at " + threeDigits(options.maxPatchArea) +
                                                       " m^2 would make " + threeDigits(plan.patchCount) +
                                                       " patches; at most 1e+09 can be indexed");
    }

    if (progress) {
        progress->done.store(0, std::memory_order_relaxed);
        progress->total.store(scene.faceCount(), std::memory_order_relaxed);
    }

    // Which pieces cut along contacts lie under what stands on them (ContactCuts.h, coveredPiece);
    // asked here, not while planning, so that estimatePatchCount() casts no rays. A caller without
    // a caster has one built only for a scene with such pieces.
    const double offset = detail::kCoveredOffset * detail::sceneDiagonal(scene);
    std::optional<RayCaster> ownRays;
    for (std::size_t s = 0; s < plan.surfaces.size(); ++s)
        for (detail::Piece& piece : plan.surfaces[s].pieces) {
            if (!piece.contactCut) continue;
            if (!rays) rays = &ownRays.emplace(scene);
            std::array<glm::dvec3, 4> corners{};
            for (std::size_t c = 0; c < piece.count; ++c) corners[c] = plan.surfaces[s].corners[piece.corners[c]];
            piece.covered = detail::coveredPiece(*rays, std::span<const glm::dvec3>(corners.data(), piece.count),
                                                 scene.surfaces[s].faces[piece.face].normal, offset);
        }

    PatchMesh mesh;
    mesh.contactCuts = plan.contacts;
    mesh.patches.reserve(saturatingCount(plan.patchCount));
    mesh.surfaceFirstPatch.reserve(scene.surfaces.size() + 1);
    for (std::size_t s = 0; s < plan.surfaces.size(); ++s) {
        mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
        const SurfacePlan& surfacePlan = plan.surfaces[s];
        SurfaceEmitter emitter(surfacePlan, static_cast<std::uint32_t>(s), mesh);
        std::size_t piece = 0;  // pieces are in face order; a degenerate face has none
        for (std::size_t face = 0; face < scene.surfaces[s].faces.size(); ++face) {
            if (progress) progress->checkCancelled();
            for (; piece < surfacePlan.pieces.size() && surfacePlan.pieces[piece].face == face; ++piece)
                emitter.emit(surfacePlan.pieces[piece]);
            if (progress) progress->done.fetch_add(1, std::memory_order_relaxed);
        }
    }
    mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
    return mesh;
}

} // namespace radiant
