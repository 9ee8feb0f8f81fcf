#pragma once
// What a hemicube's item buffer says about the point it was taken at (Cohen & Greenberg,
// SIGGRAPH 1985): each pixel holds the patch seen through it, and summing delta form factors over
// a surface's pixels gives F(dx -> surface) with occlusion resolved by the depth test.
//
//   F(dx -> j) = sum of dF over the pixels that see patch j's front side
//   E(x)       = sum over pixels of L(pixel) pi dF = sum_j B_j F(dx -> j)       (L = B / pi)
//
// Item encoding: 0 = nothing (open sky), patch + 1 otherwise, with kHemicubeBackFace set when the
// patch is seen from its back (it blocks, but a one-sided diffuse surface sends nothing that way).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/hemicube/HemicubeLayout.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

inline constexpr std::uint32_t kHemicubeEmpty = 0;
inline constexpr std::uint32_t kHemicubeBackFace = 0x80000000u;

[[nodiscard]] constexpr std::uint32_t encodeHemicubeItem(std::size_t patch, bool backFace) {
    return (static_cast<std::uint32_t>(patch) + 1u) | (backFace ? kHemicubeBackFace : 0u);
}
/// The patch a non-empty item shows.
[[nodiscard]] constexpr std::size_t hemicubeItemPatch(std::uint32_t item) {
    return static_cast<std::size_t>((item & ~kHemicubeBackFace) - 1u);
}
[[nodiscard]] constexpr bool hemicubeItemIsFront(std::uint32_t item) {
    return item != kHemicubeEmpty && (item & kHemicubeBackFace) == 0;
}

struct HemicubeSurfaceReading {
    double formFactor = 0;  ///< F(dx -> surface): front-facing pixels only
    SolidAngle solidAngle{};  ///< sr, pixels showing either side of the surface
    std::size_t pixels = 0;
};

struct HemicubeGatherResult {
    std::vector<HemicubeSurfaceReading> surfaces;  ///< indexed like Scene::surfaces
    double openFormFactor = 0;     ///< sum of dF over pixels that see nothing
    double backFaceFormFactor = 0; ///< sum of dF over pixels that see a surface's back
    double totalFormFactor = 0;    ///< sum of every pixel's dF (-> 1 as the resolution grows)
    IrradianceRgb irradiance{};    ///< W/m^2: sum_j B_j F(dx -> j); zero when no radiosity was given
};

/// Sums the layout's delta form factors over the item buffer (layout.pixelCount() items, row-major
/// from the bottom row). `radiosity` (W/m^2 per patch) may be empty. Throws RadiantError when the
/// buffer's size does not match the layout or an item names a patch outside the mesh.
HemicubeGatherResult gatherHemicube(const HemicubeLayout& layout, std::span<const std::uint32_t> items,
                                    const PatchMesh& mesh, std::size_t surfaceCount,
                                    std::span<const Rgb> radiosity = {});

} // namespace radiant
