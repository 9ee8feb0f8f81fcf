#include "radiometry/scene/EnergyBalance.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <glm/common.hpp>
#include <string>

#include "radiometry/common/Error.h"

namespace radiant {

double luminanceOf(const Rgb& rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

Rgb lightPower(const PunctualLight& light, double sceneAreaM2) {
    switch (light.type) {
    case PunctualLightType::Point: return 4 * std::numbers::pi * light.intensity.value();
    case PunctualLightType::Spot: {
        // With u = cos(angle off the axis), d omega = 2 pi du; the falloff is 1 above cos inner and
        // ((u - cos outer) / (cos inner - cos outer))^2 down to cos outer, whose integral is a third.
        const double ci = std::cos(light.innerConeAngle), co = std::cos(light.outerConeAngle);
        return 2 * std::numbers::pi * ((1 - ci) + (ci - co) / 3) * light.intensity.value();
    }
    case PunctualLightType::Directional: return sceneAreaM2 / 4 * light.normalIrradiance.value();
    }
    return Rgb(0.0);
}

EnergyBalance enclosureEnergyBalance(const Scene& scene, std::span<const std::uint32_t> patchSurface,
                                     std::span<const double> patchAreaM2) {
    if (patchSurface.size() != patchAreaM2.size())
        throw RadiantError({scene.name, "energy balance"}, std::to_string(patchSurface.size()) + " surfaces for " +
                                                               std::to_string(patchAreaM2.size()) + " patch areas");
    const auto materialOf = [&](std::size_t p) -> const Material& {
        const std::uint32_t surface = patchSurface[p];
        if (surface >= scene.surfaces.size())
            throw RadiantError({scene.name, "patch " + std::to_string(p)},
                               "surface " + std::to_string(surface) + " is not in the scene (" +
                                   std::to_string(scene.surfaces.size()) + " surfaces)");
        return scene.materials.at(scene.surfaces[surface].material);
    };
    Rgb emitted(0.0), absorbing(0.0);
    for (std::size_t p = 0; p < patchSurface.size(); ++p) {
        const Material& material = materialOf(p);
        emitted += patchAreaM2[p] * material.exitance.value();
        absorbing += patchAreaM2[p] * (Rgb(1.0) - material.reflectance);
    }
    double totalArea = 0;
    for (const double a : patchAreaM2) totalArea += a;
    for (const PunctualLight& light : scene.lights) emitted += lightPower(light, totalArea);
    // A band nothing absorbs (all reflectances 1) has no balance; the floor keeps it finite.
    const Rgb meanIrradiance = emitted / glm::max(absorbing, Rgb(1e-12));
    Rgb reflectorSum(0.0), emitterSum(0.0);
    double reflectorArea = 0, emitterArea = 0;
    for (std::size_t p = 0; p < patchSurface.size(); ++p) {
        const Material& material = materialOf(p);
        const Rgb radiosity = material.exitance.value() + material.reflectance * meanIrradiance;
        (material.emits() ? emitterSum : reflectorSum) += patchAreaM2[p] * radiosity;
        (material.emits() ? emitterArea : reflectorArea) += patchAreaM2[p];
    }
    EnergyBalance balance;
    balance.anythingEmits = std::max({emitted.x, emitted.y, emitted.z}) > 0;
    balance.meanRadiosityW_m2 = reflectorArea > 0 ? reflectorSum / reflectorArea
                                : emitterArea > 0 ? emitterSum / emitterArea
                                                  : Rgb(0.0);
    return balance;
}

} // namespace radiant
