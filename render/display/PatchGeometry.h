#pragma once
// The patch mesh as the vertices the GPU draws, GL-free: triangles for patches outside grid faces
// (with barycentric edge coordinates for the wireframe and the shooter's outline), one quad per grid
// face (FaceGrids.h) and, for the shooter's outline, one cell of a grid as a quad. Every triangle is
// wound counter-clockwise about its patch's normal, so that culling back faces (GL_BACK with
// GL_CCW front faces) draws each face from its front only: a closed room's near walls vanish like a
// cut-away, and the two sides of a two-sided face (two surfaces back to back) each show their own.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"
#include "render/display/FaceGrids.h"
#include "render/display/SmoothingGroups.h"

namespace radiant::render {

/// A vertex of a patch triangle: patch.vert.glsl's attributes 0-2.
struct PatchVertex {
    glm::vec3 position;  ///< m
    glm::vec3 edge;      ///< barycentric coordinate; 1 everywhere for the edge a fan's diagonal hides
    glm::vec3 normal;    ///< the patch's, unit
};

/// A corner of a grid face's quad, drawn with its light map: patch.vert.glsl's LIGHT_MAP attributes.
struct GridVertex {
    glm::vec3 position;  ///< m
    glm::vec3 normal;    ///< the face's, unit
    glm::vec2 grid;      ///< grid coordinates: (0, 0) .. (columns, rows)
    glm::vec3 layout;    ///< first atlas row, columns, rows
};

/// A patch corner as the indexed draw reads it: patch.vert.glsl's attributes 0 and 2.
struct CornerVertex {
    glm::vec3 position;  ///< m
    glm::vec3 normal;    ///< the patch's, unit
};

/// The same triangles twice. Indexed: one vertex per patch corner, shared by the patch's triangles
/// (a quad shades 4 vertices, not 6; software GL shades each vertex of a draw on the drawing
/// thread), for every variant without edges. Unindexed: three vertices per triangle, each carrying
/// its own barycentric edge coordinates, for the wireframe and the shooter's outline. Corners are
/// not shared between patches: tint, flat colour and normal are the patch's own.
struct PatchTriangles {
    std::vector<PatchVertex> vertices;            ///< three per triangle
    std::vector<std::uint32_t> drawnPatch;        ///< per vertex: its patch
    std::vector<std::uint32_t> drawnSmoothing;    ///< per vertex: its smoothing vertex
    std::vector<std::uint32_t> patchFirstVertex;  ///< per patch and one past the last: its vertices
    std::vector<CornerVertex> corners;            ///< per corner of each patch drawn here
    std::vector<std::uint32_t> cornerPatch;       ///< per corner: its patch
    std::vector<std::uint32_t> cornerSmoothing;   ///< per corner: its smoothing vertex
    /// Three per triangle, into corners: vertices' triangles in the same order and winding.
    std::vector<std::uint32_t> cornerIndices;
};

/// The triangles of the patches not in `grids` (fans about corner 0).
PatchTriangles patchTriangles(const PatchMesh& mesh, const FaceGrids& grids, const SmoothingGroups& smoothing);

/// Six vertices (two triangles) per grid face.
std::vector<GridVertex> gridQuads(const FaceGrids& grids);

/// Cell `cell` (row-major) of `grid` as two triangles: corners on the face's bilinear map, grid
/// coordinates as the face's quad gives them there.
std::array<GridVertex, 6> gridCellQuad(const FaceGrid& grid, std::uint32_t cell);

} // namespace radiant::render
