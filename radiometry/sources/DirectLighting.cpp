#include "radiometry/sources/DirectLighting.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/probe/PolygonSamples.h"
#include "radiometry/scene/View.h"
#include "radiometry/solver/ParallelFor.h"

namespace radiant {

DirectLighting::DirectLighting(const Scene& scene, const RayCaster* rays) : lights_(scene.lights), rays_(rays) {
    glm::dvec3 lo, hi;
    if (sceneBounds(scene, lo, hi)) sunRayLength_ = std::max(1.0, 2 * glm::length(hi - lo));
}

double spotFalloff(double cosAngle, double innerConeAngle, double outerConeAngle) {
    const double cosOuter = std::cos(outerConeAngle);
    // glTF's recommended scale: a cone whose inner and outer angles meet still ends smoothly.
    const double scale = 1.0 / std::max(0.001, std::cos(innerConeAngle) - cosOuter);
    const double t = std::clamp((cosAngle - cosOuter) * scale, 0.0, 1.0);
    return t * t;
}

Rgb DirectLighting::fromLight(const PunctualLight& light, const glm::dvec3& x, const glm::dvec3& n) const {
    if (light.type == PunctualLightType::Directional) {
        const glm::dvec3 toLight = -light.direction;
        const double cosTheta = glm::dot(n, toLight);
        if (cosTheta <= 0) return Rgb(0.0);
        if (rays_ != nullptr && rays_->occluded(x, x + sunRayLength_ * toLight)) return Rgb(0.0);
        return light.normalIrradiance.value() * cosTheta;
    }
    const glm::dvec3 d = light.position - x;
    const double r2 = glm::dot(d, d);
    if (!(r2 > 0)) return Rgb(0.0);
    const double r = std::sqrt(r2);
    const double cosTheta = glm::dot(n, d) / r;
    if (cosTheta <= 0) return Rgb(0.0);
    double falloff = 1;
    if (light.type == PunctualLightType::Spot) {
        falloff = spotFalloff(glm::dot(light.direction, -d / r), light.innerConeAngle, light.outerConeAngle);
        if (falloff <= 0) return Rgb(0.0);
    }
    if (rays_ != nullptr && rays_->occluded(x, light.position)) return Rgb(0.0);
    return light.intensity.value() * (falloff * cosTheta / r2);
}

IrradianceRgb DirectLighting::at(const glm::dvec3& x, const glm::dvec3& n) const {
    Rgb sum(0.0);
    for (const PunctualLight& light : lights_) sum += fromLight(light, x, n);
    return IrradianceRgb(sum);
}

IrradianceRgb DirectLighting::meanOver(const PatchPolygon& polygon, int perSide, std::uint64_t seed) const {
    if (lights_.empty() || !(polygon.area > 0)) return IrradianceRgb{};
    std::vector<PolygonSample> samples;
    stratifiedPolygonSamples(polygon, perSide, seed, samples);
    Rgb sum(0.0);
    double area = 0;
    for (const PolygonSample& s : samples) {
        sum += s.area * at(s.point, polygon.normal).value();
        area += s.area;
    }
    return IrradianceRgb(area > 0 ? sum / area : Rgb(0.0));
}

std::vector<Rgb> meanDirectIrradiance(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays, std::uint64_t seed) {
    std::vector<Rgb> direct(mesh.size(), Rgb(0.0));
    if (scene.lights.empty()) return direct;
    const DirectLighting lighting(scene, rays);
    parallelFor(mesh.size(), 256, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Patch& patch = mesh.patches[i];
            // A patch made by hand without corners is lit at its centroid.
            direct[i] = patch.cornerCount >= 3
                            ? lighting.meanOver(mesh.polygon(i), DirectLighting::kSamplesPerSide, mixBits(seed ^ mixBits(i))).value()
                            : lighting.at(patch.centroid, patch.normal).value();
        }
    });
    return direct;
}

} // namespace radiant
