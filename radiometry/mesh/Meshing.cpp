// Meshing: every face into a conforming grid of patches, quads on quads and triangles on triangles.
// The segment counts come from detail::planMeshing (see MeshPlan.h); this file only emits them.
// Vertices on an edge are made once and shared by both pieces that meet there, so the mesh has no
// T-junctions within a surface (Baum, Mann, Smith and Winget, "Making radiosity usable: automatic
// preprocessing and meshing techniques for the generation of accurate radiosity solutions",
// SIGGRAPH 1991, on why T-junctions show as cracks and shading seams).
#include <cstdio>
#include <limits>
#include <string>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/MeshPlan.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant {
namespace {

using detail::Piece;
using detail::SurfacePlan;

std::string describe(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

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

    // Barycentric lattice (i, j): point p0 + i/n (p1 - p0) + j/n (p2 - p0), i + j <= n.
    void emitTriangle(const Piece& piece) {
        const std::uint64_t n = plan_.segments(piece.edges[0]);
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
        const auto at = [&](std::uint64_t i, std::uint64_t j) -> std::uint32_t {
            if (j == 0) return onEdge(piece, 0, i);
            if (i + j == n) return onEdge(piece, 1, j);
            if (i == 0) return onEdge(piece, 2, n - j);
            return rowStart[j] + static_cast<std::uint32_t>(i - 1);
        };
        for (std::uint64_t j = 0; j < n; ++j)
            for (std::uint64_t i = 0; i + j < n; ++i) {
                addPatch(piece, {at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j + 1 < n) addPatch(piece, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
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

PatchMesh meshScene(const Scene& scene, const MeshingOptions& options, Progress* progress) {
    const detail::MeshPlan plan = detail::planMeshing(scene, options);
    if (plan.patchCount > static_cast<double>(options.patchBudget)) {
        throw BudgetError({scene.name, "meshing"},
                          "meshing at " + describe(options.maxPatchArea) + " m^2 would make " +
                              describe(plan.patchCount) + " patches; the budget is " +
                              describe(static_cast<double>(options.patchBudget)));
    }
    // Vertex indices are 32-bit: refuse what they cannot address, whatever the budget says.
    if (plan.patchCount > 1e9) {
        throw BudgetError({scene.name, "meshing"}, "meshing at " + describe(options.maxPatchArea) +
                                                       " m^2 would make " + describe(plan.patchCount) +
                                                       " patches; at most 1e+09 can be indexed");
    }

    if (progress) {
        progress->done.store(0, std::memory_order_relaxed);
        progress->total.store(scene.faceCount(), std::memory_order_relaxed);
    }

    PatchMesh mesh;
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
