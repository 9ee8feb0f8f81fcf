#include "render/display/DisplayBuffers.h"

namespace radiant::render {

void fillDisplayVertices(std::span<const std::uint32_t> patchOf, std::span<const std::uint32_t> smoothingOf,
                         const DisplayColours& colours, std::vector<DisplayVertex>& out) {
    out.resize(patchOf.size());
    for (std::size_t v = 0; v < out.size(); ++v) {
        const std::uint32_t patch = patchOf[v];
        out[v] = {colours.smooth ? colours.vertex[smoothingOf[v]] : colours.patch[patch], colours.tint[patch]};
    }
}

glm::vec4 tintTexel(const Tint& tint) {
    const bool outlined = tint.w >= 2.0f;
    return {glm::vec3(tint), outlined ? 0.5f + (tint.w - 2.0f) / 2.0f : tint.w / 2.0f};
}

void fillAtlasTexels(const FaceGrids& grids, const SmoothingGroups& smoothing, const DisplayColours& colours,
                     std::vector<glm::vec4>& colourTexels, std::vector<glm::vec4>& tintTexels) {
    const std::size_t width = grids.atlasWidth;
    colourTexels.resize(width * grids.atlasHeight);
    tintTexels.resize(width * grids.atlasHeight);
    for (const FaceGrid& grid : grids.grids) {
        const std::size_t n = grid.columns, m = grid.rows, row = grid.atlasRow;
        for (std::size_t j = 0; j < m; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint32_t patch = grid.cellPatch[j * n + i];
                tintTexels[(row + j) * width + i] = tintTexel(colours.tint[patch]);
                if (!colours.smooth) colourTexels[(row + j) * width + i] = colours.patch[patch];
            }
        if (colours.smooth)
            for (std::size_t j = 0; j <= m; ++j)
                for (std::size_t i = 0; i <= n; ++i) {
                    const std::uint32_t corner = grid.vertexCorner[j * (n + 1) + i];
                    colourTexels[(row + j) * width + i] = colours.vertex[smoothing.cornerVertex[corner / 4][corner % 4]];
                }
    }
}

} // namespace radiant::render
