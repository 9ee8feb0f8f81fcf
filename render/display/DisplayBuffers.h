#pragma once
// The display colours laid out as the GPU reads them, GL-free: per drawn triangle vertex (colour and
// tint attributes), and as texels of the grid faces' atlases (FaceGrids.h). The drawer uploads these
// arrays as they are.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "render/display/DisplayModel.h"
#include "render/display/PatchGeometry.h"

namespace radiant::render {

/// The part of a drawn vertex that changes with the solution and the display settings: vertex
/// attributes 3 and 4. Attributes rather than buffer textures: llvmpipe's texelFetch per vertex cost
/// more than the frame.
struct DisplayVertex {
    glm::vec4 colour;  ///< rgb: sRGB display colour; a: position on the colour map
    Tint tint;         ///< rgb: colour to mix toward; a: amount, +2 when the patch is outlined
};

/// Gouraud: each drawn vertex takes its smoothing vertex's colour; flat: its patch's. `patchOf` and
/// `smoothingOf` name each vertex's (PatchTriangles' drawn or corner arrays).
void fillDisplayVertices(std::span<const std::uint32_t> patchOf, std::span<const std::uint32_t> smoothingOf,
                         const DisplayColours& colours, std::vector<DisplayVertex>& out);

/// A tint as an 8-bit texel can hold it: alpha = amount / 2, + 1/2 when outlined (an amount is at
/// most 0.8: importance, changed and shooter tints combined). patch.frag.glsl decodes it.
glm::vec4 tintTexel(const Tint& tint);

/// The atlases' texels (atlasWidth x atlasHeight, row-major): grid vertex (i, j) of a grid at atlas
/// row r is texel (i, r + j) of `colourTexels` when smooth, else cell (i, j) holds its patch's
/// colour; `tintTexels` holds cell (i, j)'s tintTexel. Texels outside the grids are left as they are.
void fillAtlasTexels(const FaceGrids& grids, const SmoothingGroups& smoothing, const DisplayColours& colours,
                     std::vector<glm::vec4>& colourTexels, std::vector<glm::vec4>& tintTexels);

} // namespace radiant::render
