#include "render/display/PatchGeometry.h"

#include <glm/geometric.hpp>

namespace radiant::render {
namespace {

/// The quad's corner order for its two triangles (0 1 2, 0 2 3), mirrored (0 2 1, 0 3 2) when the
/// corners run clockwise about `normal`.
std::array<int, 6> quadOrder(const std::array<glm::dvec3, 4>& corners, const glm::dvec3& normal) {
    const bool counterClockwise = glm::dot(glm::cross(corners[1] - corners[0], corners[3] - corners[0]), normal) >= 0;
    return counterClockwise ? std::array<int, 6>{0, 1, 2, 0, 2, 3} : std::array<int, 6>{0, 2, 1, 0, 3, 2};
}

GridVertex gridVertexAt(const FaceGrid& grid, std::uint32_t column, std::uint32_t row) {
    const double u = static_cast<double>(column) / grid.columns, v = static_cast<double>(row) / grid.rows;
    const std::array<glm::dvec3, 4>& c = grid.corners;
    const glm::dvec3 position = c[0] + (c[1] - c[0]) * u + (c[3] - c[0]) * v + (c[0] - c[1] + c[2] - c[3]) * (u * v);
    return {glm::vec3(position), glm::vec3(grid.normal), glm::vec2(static_cast<float>(column), static_cast<float>(row)),
            glm::vec3(static_cast<float>(grid.atlasRow), static_cast<float>(grid.columns), static_cast<float>(grid.rows))};
}

} // namespace

PatchTriangles patchTriangles(const PatchMesh& mesh, const FaceGrids& grids, const SmoothingGroups& smoothing) {
    const std::size_t n = mesh.patches.size();
    PatchTriangles t;
    t.vertices.reserve(n * 6);
    t.corners.reserve(n * 4);
    t.patchFirstVertex.assign(n + 1, 0);
    for (std::size_t p = 0; p < n; ++p) {
        t.patchFirstVertex[p] = static_cast<std::uint32_t>(t.vertices.size());
        if (grids.patchInGrid[p]) continue;  // drawn by its face's light map
        const Patch& patch = mesh.patches[p];
        const auto firstCorner = static_cast<std::uint32_t>(t.corners.size());
        for (std::uint8_t c = 0; c < patch.cornerCount; ++c) {
            t.corners.push_back({glm::vec3(mesh.vertices[patch.corners[c]]), glm::vec3(patch.normal)});
            t.cornerPatch.push_back(static_cast<std::uint32_t>(p));
            t.cornerSmoothing.push_back(smoothing.cornerVertex[p][c]);
        }
        const auto corner = [&](std::uint8_t c, const glm::vec3& edge) {
            t.vertices.push_back({glm::vec3(mesh.vertices[patch.corners[c]]), edge, glm::vec3(patch.normal)});
            t.drawnPatch.push_back(static_cast<std::uint32_t>(p));
            t.drawnSmoothing.push_back(smoothing.cornerVertex[p][c]);
            t.cornerIndices.push_back(firstCorner + c);
        };
        // Fan about corner 0. Barycentric coordinate k is 1 at the triangle's vertex k and 0 on the
        // edge opposite; for a fan's inner diagonal (not a patch edge) that coordinate is held at 1,
        // so the wireframe and the shooter outline show patch edges only.
        for (std::uint8_t i = 1; i + 1 < patch.cornerCount; ++i) {
            const auto j = static_cast<std::uint8_t>(i + 1);
            const float diagonalZ = i == 1 ? 0.0f : 1.0f;                      // edge corner 0 - corner i
            const float diagonalY = i + 2 == patch.cornerCount ? 0.0f : 1.0f;  // edge corner 0 - corner i+1
            const glm::dvec3 a = mesh.vertices[patch.corners[0]], b = mesh.vertices[patch.corners[i]],
                             c = mesh.vertices[patch.corners[j]];
            corner(0, {1, diagonalY, diagonalZ});
            // Swapping the last two vertices swaps their barycentric axes: the edge coordinates
            // follow their vertices, so each edge keeps its own.
            if (glm::dot(glm::cross(b - a, c - a), patch.normal) >= 0) {
                corner(i, {0, 1, diagonalZ});
                corner(j, {0, diagonalY, 1});
            } else {
                corner(j, {0, diagonalY, 1});
                corner(i, {0, 1, diagonalZ});
            }
        }
    }
    t.patchFirstVertex[n] = static_cast<std::uint32_t>(t.vertices.size());
    return t;
}

std::vector<GridVertex> gridQuads(const FaceGrids& grids) {
    std::vector<GridVertex> quads;
    quads.reserve(grids.grids.size() * 6);
    for (const FaceGrid& grid : grids.grids) {
        const std::array<GridVertex, 4> corners{gridVertexAt(grid, 0, 0), gridVertexAt(grid, grid.columns, 0),
                                                gridVertexAt(grid, grid.columns, grid.rows),
                                                gridVertexAt(grid, 0, grid.rows)};
        for (const int k : quadOrder(grid.corners, grid.normal)) quads.push_back(corners[static_cast<std::size_t>(k)]);
    }
    return quads;
}

std::array<GridVertex, 6> gridCellQuad(const FaceGrid& grid, std::uint32_t cell) {
    const std::uint32_t i = cell % grid.columns, j = cell / grid.columns;
    const std::array<GridVertex, 4> corners{gridVertexAt(grid, i, j), gridVertexAt(grid, i + 1, j),
                                            gridVertexAt(grid, i + 1, j + 1), gridVertexAt(grid, i, j + 1)};
    std::array<GridVertex, 6> quad{};
    std::size_t k = 0;
    for (const int corner : quadOrder(grid.corners, grid.normal)) quad[k++] = corners[static_cast<std::size_t>(corner)];
    return quad;
}

} // namespace radiant::render
