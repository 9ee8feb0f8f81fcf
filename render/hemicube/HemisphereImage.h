#pragma once
// Colours a disk view of the hemisphere (HemisphereProjection.h) from a hemicube's item buffer:
// each surface in its display colour, or the radiance L = B / pi it sends toward the point, or the
// delta form factors as a heat map; with the theta/phi grid of d omega cells and the target surface
// outlined. GL-free: pixels in memory, which ImageTexture uploads and tests inspect.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/hemicube/HemisphereProjection.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/units/Quantity.h"
#include "render/hemicube/HemicubeRenderer.h"

namespace radiant::render {

enum class HemisphereColouring {
    Surfaces,        ///< each surface in its material's display colour, shaded by how squarely it faces the point
    Radiance,        ///< L = B / pi of the patch seen, L / radianceScale tone-mapped (Reinhard)
    DeltaFormFactor  ///< the hemicube pixel's dF relative to the largest (dA / pi at the zenith)
};

struct HemisphereImageOptions {
    HemisphereColouring colouring = HemisphereColouring::Surfaces;
    std::optional<std::size_t> targetSurface;  ///< outlined in yellow
    bool grid = true;                          ///< theta every 15 degrees, phi every 30 degrees
    double radianceScale = 0;                  ///< W/(m^2 sr) mapped to mid-grey; 0: twice the mean seen
    std::uint8_t openSkyAlpha = 255;           ///< alpha where the point sees nothing (the 3D dome: see-through)
};

/// The delta form factor heat map's ramp (dark blue -> teal -> yellow), linear RGB, at t = dF / (dA / pi)
/// in [0, 1] (clamped): the image and the Hemisphere panel's colour scale share it.
glm::vec3 deltaFormFactorHeat(float t);

/// RGBA8, map.size() squared pixels, top row first; outside the disk transparent, open sky openSkyAlpha.
/// `surfaceColours` (linear RGB per surface) is used for Surfaces; `radiosity` (W/m^2 per patch) for Radiance.
/// `map` must have been made for capture.layout.
std::vector<std::uint8_t> hemisphereImage(const HemisphereViewMap& map, const HemicubeCapture& capture,
                                          const PatchMesh& mesh,
                                          std::span<const glm::vec3> surfaceColours, std::span<const Rgb> radiosity,
                                          const HemisphereImageOptions& options);

} // namespace radiant::render
