#pragma once
// Faces that meshing cut into an n x m grid of quads (a quad face is cut bilinearly: see
// radiometry/mesh/MeshPlan.h) can be drawn as one quad sampling a small texture of their patches'
// colours, a light map, instead of 2nm triangles. On software GL (llvmpipe) the vertex stage and
// binning run on the drawing thread: 40k triangles (the Cornell box at 20k patches) took 8-11 ms of
// it per frame, its 22 grid faces as quads ~1 ms (the pixels cost about the same either way), and
// a new solution uploads a texel per patch instead of six 32-byte vertices. This finds those grids
// in a mesh; other patches (triangular or fanned faces) stay triangles. GL-free.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"

namespace radiant::render {

struct FaceGrid {
    std::uint32_t columns = 0;  ///< n: cells along corner 0 -> 1
    std::uint32_t rows = 0;     ///< m: cells along corner 0 -> 3
    /// The face's corners, at grid coordinates (0, 0), (n, 0), (n, m), (0, m).
    std::array<glm::dvec3, 4> corners{};
    glm::dvec3 normal{0, 0, 1};
    std::uint32_t atlasRow = 0;  ///< its texels are rows atlasRow .. atlasRow + m of the atlas
    /// Row-major n x m: the patch in cell (i, j).
    std::vector<std::uint32_t> cellPatch;
    /// Row-major (n + 1) x (m + 1): a patch corner at grid vertex (i, j), as patch * 4 + corner.
    std::vector<std::uint32_t> vertexCorner;
};

struct FaceGrids {
    std::vector<FaceGrid> grids;
    std::vector<char> patchInGrid;  ///< per patch: drawn by its grid, not as triangles
    /// The atlas holds every grid's (n + 1) x (m + 1) texels, grids stacked in rows.
    std::uint32_t atlasWidth = 1, atlasHeight = 1;
};

/// The faces of `mesh` whose patches form a bilinear n x m grid of their four corners (within a
/// relative 1e-4 of a cell). Faces that do not are left out, so the result is always drawable.
FaceGrids findFaceGrids(const Scene& scene, const PatchMesh& mesh);

} // namespace radiant::render
