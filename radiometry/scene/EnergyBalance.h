#pragma once
// The radiosity a closed enclosure settles at, from its materials alone: at convergence all emitted
// power P is absorbed, P = sum_i A_i (1 - rho_i) H (per band), so if the light were well mixed every
// patch would see the mean irradiance H = P / sum_i A_i (1 - rho_i) and leave with E_i + rho_i H.
// Exact for the furnace (every patch emits E and reflects rho: B = E / (1 - rho)); for other scenes
// an estimate of the light's level before any solve, which the display keys its exposure on.
// glTF lights add their power to P (lightPower): all of a point or spot light's, and for a sun the
// power a convex body of the scene's area would intercept (Cauchy: its mean projected area is A / 4).
#include <cstdint>
#include <span>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct EnergyBalance {
    bool anythingEmits = false;
    /// Area mean of E + rho H over the non-emitting patches, or over every patch when all emit
    /// (the furnace); zero when there is no patch. W/m^2 per band.
    Rgb meanRadiosityW_m2{0.0};
};

/// The balance of patches with the given surfaces (indices into scene.surfaces) and areas (m^2);
/// the spans have one entry per patch. A surface index outside the scene throws RadiantError.
EnergyBalance enclosureEnergyBalance(const Scene& scene, std::span<const std::uint32_t> patchSurface,
                                     std::span<const double> patchAreaM2);

/// The power a light sends out, W per band: 4 pi I for a point; for a spot I times its cone's
/// solid angle weighted by glTF's falloff, 2 pi [(1 - cos inner) + (cos inner - cos outer) / 3];
/// for a sun its normal irradiance over A / 4, `sceneAreaM2` being the scene's area A.
Rgb lightPower(const PunctualLight& light, double sceneAreaM2);

/// Photometric luminance weights (Rec. 709) of linear RGB: 0.2126 R + 0.7152 G + 0.0722 B.
double luminanceOf(const Rgb& rgb);

} // namespace radiant
