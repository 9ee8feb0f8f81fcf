#pragma once
// The direct irradiance H of a scene's punctual lights (PunctualLight.h) with shadow rays: at a
// point (the probe, the reference tracer's next-event estimate) and averaged over a patch or element
// (the solvers' source term B = E + rho (H + F B)). A patch's mean is taken at stratified jittered
// points (PolygonSamples.h), one shadow ray per point and light: a penumbra's share is resolved to
// the strata, and a lit patch's mean of I cos / r^2 converges to I times the solid angle the patch
// subtends from the light, over its area.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

class RayCaster;

class DirectLighting {
public:
    /// Copies the scene's lights. rays (built on the same scene) must outlive this; null: no shadows.
    DirectLighting(const Scene& scene, const RayCaster* rays);

    [[nodiscard]] bool empty() const { return lights_.empty(); }
    [[nodiscard]] const std::vector<PunctualLight>& lights() const { return lights_; }

    /// H at x on a surface whose front faces n (unit): every light the front sees, unshaded.
    [[nodiscard]] IrradianceRgb at(const glm::dvec3& x, const glm::dvec3& n) const;
    /// The area-weighted mean of H over the polygon's front, from perSide^2 stratified points.
    [[nodiscard]] IrradianceRgb meanOver(const PatchPolygon& polygon, int perSide, std::uint64_t seed) const;

    /// Points per side for a patch or element: 16 shadow rays per light.
    static constexpr int kSamplesPerSide = 4;

private:
    [[nodiscard]] Rgb fromLight(const PunctualLight& light, const glm::dvec3& x, const glm::dvec3& n) const;

    std::vector<PunctualLight> lights_;
    const RayCaster* rays_;
    double sunRayLength_ = 1;  ///< m: from anywhere in the scene to beyond its bounds
};

/// glTF's spot falloff (PunctualLight.h) for a direction at cosine cosAngle off the spot's axis.
double spotFalloff(double cosAngle, double innerConeAngle, double outerConeAngle);

/// H averaged over every patch of the mesh (parallel over patches); all zero without lights.
std::vector<Rgb> meanDirectIrradiance(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays,
                                      std::uint64_t seed = 1);

} // namespace radiant
