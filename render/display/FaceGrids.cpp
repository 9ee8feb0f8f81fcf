#include "render/display/FaceGrids.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <optional>
#include <utility>

namespace radiant::render {
namespace {

constexpr std::uint32_t kMaxAtlasSide = 8192;

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

/// (u, v) with p = a + (b - a) u + (d - a) v + (a - b + c - d) u v, for p in the plane of the convex
/// quad abcd (2D, the plane's coordinates): the inverse of the bilinear map (I. Quilez's closed form).
std::optional<glm::dvec2> inverseBilinear(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                                          const glm::dvec2& c, const glm::dvec2& d) {
    const glm::dvec2 e = b - a, f = d - a, g = a - b + c - d, h = p - a;
    const double k2 = cross(g, f), k1 = cross(e, f) + cross(h, g), k0 = cross(h, e);
    const double scale = std::max(std::abs(cross(e, f)), 1e-300);
    double v;
    if (std::abs(k2) < 1e-12 * scale) {
        if (std::abs(k1) < 1e-300) return std::nullopt;
        v = -k0 / k1;
    } else {
        const double w = k1 * k1 - 4.0 * k0 * k2;
        if (w < 0) return std::nullopt;
        const double root = std::sqrt(w);
        v = (-k1 - root) / (2.0 * k2);
        if (v < -1e-6 || v > 1 + 1e-6) v = (-k1 + root) / (2.0 * k2);
    }
    const glm::dvec2 across = e + g * v, along = h - f * v;
    const double u = std::abs(across.x) > std::abs(across.y) ? along.x / across.x : along.y / across.y;
    return glm::dvec2(u, v);
}

/// The grid of one face's patches, or nothing when they are not one.
std::optional<FaceGrid> gridOf(const Face& face, const PatchMesh& mesh, const std::vector<std::uint32_t>& patches) {
    if (face.vertices.size() != 4 || patches.empty()) return std::nullopt;
    FaceGrid grid;
    for (int k = 0; k < 4; ++k) grid.corners[k] = face.vertices[k];
    grid.normal = face.normal;
    const glm::dvec3 axisU = glm::normalize(grid.corners[1] - grid.corners[0]);
    const glm::dvec3 axisV = glm::normalize(glm::cross(face.normal, axisU));
    const auto flat = [&](const glm::dvec3& p) {
        return glm::dvec2(glm::dot(p - grid.corners[0], axisU), glm::dot(p - grid.corners[0], axisV));
    };
    const glm::dvec2 a = flat(grid.corners[0]), b = flat(grid.corners[1]), c = flat(grid.corners[2]), d = flat(grid.corners[3]);

    // Every corner's (u, v); the grid's lines are the distinct values.
    std::vector<std::array<glm::dvec2, 4>> params(patches.size());
    std::vector<double> us, vs;
    for (std::size_t k = 0; k < patches.size(); ++k) {
        const Patch& patch = mesh.patches[patches[k]];
        if (patch.cornerCount != 4) return std::nullopt;
        for (int corner = 0; corner < 4; ++corner) {
            const std::optional<glm::dvec2> uv = inverseBilinear(flat(mesh.vertices[patch.corners[corner]]), a, b, c, d);
            if (!uv) return std::nullopt;
            params[k][corner] = *uv;
            us.push_back(uv->x);
            vs.push_back(uv->y);
        }
    }
    const auto lines = [](std::vector<double>& values) {
        std::sort(values.begin(), values.end());
        std::size_t distinct = 0;
        for (std::size_t i = 0; i < values.size(); ++i)
            if (i == 0 || values[i] - values[i - 1] > 1e-6) ++distinct;
        return distinct;
    };
    const std::size_t uLines = lines(us), vLines = lines(vs);
    if (uLines < 2 || vLines < 2 || (uLines - 1) * (vLines - 1) != patches.size()) return std::nullopt;
    grid.columns = static_cast<std::uint32_t>(uLines - 1);
    grid.rows = static_cast<std::uint32_t>(vLines - 1);
    const std::size_t n = grid.columns, m = grid.rows;

    constexpr std::uint32_t kUnset = 0xFFFF'FFFFu;
    grid.cellPatch.assign(n * m, kUnset);
    grid.vertexCorner.assign((n + 1) * (m + 1), kUnset);
    for (std::size_t k = 0; k < patches.size(); ++k) {
        glm::dvec2 centre(0.0);
        for (int corner = 0; corner < 4; ++corner) {
            const glm::dvec2 g = params[k][corner] * glm::dvec2(n, m);
            const glm::dvec2 vertex = glm::round(g);
            // Lines at i/n exactly, as meshing puts them (a relative 1e-4 of a cell).
            if (glm::any(glm::greaterThan(glm::abs(g - vertex), glm::dvec2(1e-4))) || vertex.x < 0 || vertex.y < 0 ||
                vertex.x > static_cast<double>(n) || vertex.y > static_cast<double>(m))
                return std::nullopt;
            grid.vertexCorner[static_cast<std::size_t>(vertex.y) * (n + 1) + static_cast<std::size_t>(vertex.x)] =
                patches[k] * 4 + static_cast<std::uint32_t>(corner);
            centre += g / 4.0;
        }
        const auto i = static_cast<std::size_t>(std::floor(centre.x)), j = static_cast<std::size_t>(std::floor(centre.y));
        if (i >= n || j >= m || grid.cellPatch[j * n + i] != kUnset) return std::nullopt;
        grid.cellPatch[j * n + i] = patches[k];
    }
    if (std::find(grid.vertexCorner.begin(), grid.vertexCorner.end(), kUnset) != grid.vertexCorner.end())
        return std::nullopt;
    return grid;
}

} // namespace

FaceGrids findFaceGrids(const Scene& scene, const PatchMesh& mesh) {
    FaceGrids result;
    result.patchInGrid.assign(mesh.size(), 0);
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces;
    for (std::size_t p = 0; p < mesh.size(); ++p)
        faces[{mesh.patches[p].surface, mesh.patches[p].face}].push_back(static_cast<std::uint32_t>(p));
    std::uint32_t row = 0;
    for (const auto& [key, patches] : faces) {
        const auto [surface, face] = key;
        if (surface >= scene.surfaces.size() || face >= scene.surfaces[surface].faces.size()) continue;
        std::optional<FaceGrid> grid = gridOf(scene.surfaces[surface].faces[face], mesh, patches);
        // Within every GL's texture size limit (8192 rows); the rest stay triangles.
        if (!grid || grid->columns + 1 > kMaxAtlasSide || row + grid->rows + 1 > kMaxAtlasSide) continue;
        grid->atlasRow = row;
        row += grid->rows + 1;
        result.atlasWidth = std::max(result.atlasWidth, grid->columns + 1);
        for (const std::uint32_t p : patches) result.patchInGrid[p] = 1;
        result.grids.push_back(std::move(*grid));
    }
    result.atlasHeight = std::max(row, 1u);
    return result;
}

} // namespace radiant::render
