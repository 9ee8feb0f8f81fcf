#pragma once
// What every matrix-free or matrix-based solver of this folder shares: per-patch materials that
// setMaterial() edits, the normalisation of residuals by emitted power, and per-pair seeds.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

class RayCaster;

/// Per-patch copies of area and material, so a solver owns its inputs and one surface's material
/// can change without touching the scene (several surfaces may share a scene material).
struct PatchMaterials {
    std::vector<double> area;          ///< m^2
    std::vector<Rgb> reflectance;      ///< per band, [0, 1)
    std::vector<Rgb> exitance;         ///< W/m^2 per band
    /// H: the scene's punctual lights' direct irradiance averaged over the patch (DirectLighting.h),
    /// W/m^2 per band; zero without lights.
    std::vector<Rgb> directIrradiance;
    /// The source term every solver starts from and gathers onto: E + rho H, W/m^2 per band. The
    /// lights' reflected direct light joins the emission, so B = source + rho F B.
    std::vector<Rgb> source;
    std::vector<std::uint32_t> surfaceFirstPatch;  ///< as PatchMesh::surfaceFirstPatch

    /// Throws RadiantError when a material is out of range or the mesh does not match the scene.
    /// Casts the lights' shadow rays when the scene has lights: through `rays` (the scene's caster)
    /// when given, else through a caster of its own.
    static PatchMaterials from(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays = nullptr);

    [[nodiscard]] std::size_t size() const { return area.size(); }
    [[nodiscard]] std::size_t surfaceCount() const { return surfaceFirstPatch.size() - 1; }
    /// Sets every patch of `surface`; validates like from() and names the surface in errors.
    void setSurface(std::size_t surface, const Rgb& newReflectance, const ExitanceRgb& newExitance);
    /// sum_i A_i (E_i + rho_i H_i) per band, W: the power the system is driven by (emitted, and the
    /// lights' first reflection), so a scene lit only by lights has a scale for its residual.
    [[nodiscard]] Rgb emittedPower() const;
};

/// The residual convention of every solver here: max over bands of power[b] / emitted[b], W/W.
/// A band that emits nothing is measured against the brightest band's emitted power, so a dark
/// band never divides by zero; a scene that emits nothing reports the unnormalised power in W.
double fractionOfEmitted(const Rgb& power, const Rgb& emitted);

/// A well-mixed seed for the pair (i, j), so every form factor's stratified jitter depends on the
/// solver's seed and the pair only - not on which thread computed it or in which order.
std::uint64_t pairSeed(std::uint64_t seed, std::size_t i, std::size_t j);

} // namespace radiant
