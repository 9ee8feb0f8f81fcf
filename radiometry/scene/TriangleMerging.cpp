#include "radiometry/scene/TriangleMerging.h"

#include <algorithm>
#include <array>
#include <limits>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/mesh/VertexWelder.h"
#include "radiometry/scene/FlatRegions.h"

namespace radiant::detail {
namespace {

// Two triangles are coplanar when their normals agree to ~1e-5 rad: float positions of a flat
// wall stay well inside, the Cornell box's warped left wall (~3e-3 rad) stays two triangles.
constexpr double kCoplanarCosine = 1.0 - 5e-11;

// Grouped flat regions pair only into quads whose opposite sides are within this ratio: a quad's
// opposite edges share one segment count, so a strip of trapezoids across a cylinder's cap (its
// outline's triangulation) passed the diameter's count to the short chords by the rim. Measured on
// tests/data/grouping/cylinder_room.gltf: the cap at 0.005 m^2 is 262 patches with the limit, 335
// without; 2 and 5 gave 270 and 485.
constexpr double kGroupedQuadRatio = 3;

bool strictlyConvex(const std::array<glm::dvec3, 4>& q, const glm::dvec3& normal) {
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 a = q[(i + 1) % 4] - q[i], b = q[(i + 2) % 4] - q[(i + 1) % 4];
        // A corner must turn left by more than a sliver of angle (collinear corners would hide a
        // vertex other faces may share).
        if (glm::dot(glm::cross(a, b), normal) <= 1e-6 * glm::length(a) * glm::length(b)) return false;
    }
    return true;
}

/// Coplanar triangles sharing an edge paired into strictly convex quads, best pairs first (see the
/// header); with `grouped`, only quads whose opposite sides are within kGroupedQuadRatio.
std::vector<Face> pairIntoFaces(const std::vector<glm::dvec3>& points, const std::vector<std::array<std::uint32_t, 3>>& welded,
                                bool grouped) {
    // Directed edge a -> b of triangle t; the neighbour across it holds b -> a.
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; };
    std::unordered_map<std::uint64_t, std::uint32_t> edgeOwner;
    for (std::uint32_t t = 0; t < welded.size(); ++t)
        for (std::size_t i = 0; i < 3; ++i) edgeOwner.emplace(key(welded[t][i], welded[t][(i + 1) % 3]), t);

    std::vector<glm::dvec3> normals;
    normals.reserve(welded.size());
    for (const auto& t : welded) {
        const glm::dvec3 n = glm::cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
        const double length = glm::length(n);
        normals.push_back(length > 0 ? n / length : glm::dvec3(0.0));
    }

    // Candidate pairs, best first: a pair whose shared edge is the longest edge of both triangles
    // is a quad's diagonal (an exporter's split), so those pair before pairs across quad borders.
    struct Candidate {
        double score;
        std::uint32_t t, u;
        std::array<glm::dvec3, 4> quad;
    };
    const auto longestSquared = [&](const std::array<std::uint32_t, 3>& tri) {
        double longest = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const glm::dvec3 e = points[tri[(i + 1) % 3]] - points[tri[i]];
            longest = std::max(longest, glm::dot(e, e));
        }
        return longest;
    };
    std::vector<Candidate> candidates;
    for (std::uint32_t t = 0; t < welded.size(); ++t) {
        const auto& tri = welded[t];
        for (std::size_t i = 0; i < 3; ++i) {
            const std::uint32_t a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
            const auto across = edgeOwner.find(key(b, a));
            if (across == edgeOwner.end() || across->second <= t) continue;  // each pair once
            const std::uint32_t u = across->second;
            if (glm::dot(normals[t], normals[u]) < kCoplanarCosine) continue;
            std::uint32_t w = welded[u][0];
            for (std::uint32_t v : welded[u])
                if (v != a && v != b) w = v;
            const std::array<glm::dvec3, 4> quad{points[a], points[w], points[b], points[c]};
            if (!strictlyConvex(quad, normals[t])) continue;
            const glm::dvec3 shared = points[b] - points[a];
            const double score = glm::dot(shared, shared) / std::max(longestSquared(tri), longestSquared(welded[u]));
            if (grouped) {
                const double e0 = glm::distance(quad[0], quad[1]), e1 = glm::distance(quad[1], quad[2]);
                const double e2 = glm::distance(quad[2], quad[3]), e3 = glm::distance(quad[3], quad[0]);
                if (std::max(e0, e2) > kGroupedQuadRatio * std::min(e0, e2) || std::max(e1, e3) > kGroupedQuadRatio * std::min(e1, e3)) continue;
            }
            candidates.push_back({score, t, u, quad});
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.score > y.score; });

    std::vector<bool> used(welded.size(), false);
    std::vector<Face> faces;
    faces.reserve(welded.size());
    for (const Candidate& candidate : candidates) {
        if (used[candidate.t] || used[candidate.u]) continue;
        used[candidate.t] = used[candidate.u] = true;
        Face face;
        face.vertices.assign(candidate.quad.begin(), candidate.quad.end());
        face.updateGeometry();
        faces.push_back(std::move(face));
    }
    for (std::uint32_t t = 0; t < welded.size(); ++t) {
        if (used[t]) continue;
        Face face;
        face.vertices = {points[welded[t][0]], points[welded[t][1]], points[welded[t][2]]};
        face.updateGeometry();
        faces.push_back(std::move(face));
    }
    return faces;
}

} // namespace

std::vector<Face> mergeTriangles(const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles, bool removeFlat) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    VertexWelder welder(std::max(1e-9 * (positions.empty() ? 1.0 : glm::length(hi - lo)), 1e-12));
    std::vector<std::array<std::uint32_t, 3>> welded;
    welded.reserve(triangles.size());
    for (const auto& t : triangles) welded.push_back({welder.weld(positions[t[0]]), welder.weld(positions[t[1]]), welder.weld(positions[t[2]])});
    const std::vector<glm::dvec3>& points = welder.points();
    std::vector<Face> asGiven = pairIntoFaces(points, welded, false);
    if (!removeFlat) return asGiven;
    std::vector<Face> grouped = pairIntoFaces(points, removeFlatVertices(points, welded, kCoplanarCosine), true);
    // Grouping pays where a surface is tessellated finer than its shape needs. Where it does not
    // even halve the faces, the given ones are already about the shape's own (the Cornell box's
    // ceiling: 8 quads around the light, which the outline's triangles would mesh worse).
    return 2 * grouped.size() <= asGiven.size() ? grouped : asGiven;
}

} // namespace radiant::detail
