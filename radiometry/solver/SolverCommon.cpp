#include "radiometry/solver/SolverCommon.h"

#include <algorithm>
#include <optional>
#include <string>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/sources/DirectLighting.h"

namespace radiant {

namespace {

void checkMaterial(const std::string& where, const Rgb& reflectance, const Rgb& exitance) {
    for (int band = 0; band < 3; ++band) {
        if (!(reflectance[band] >= 0.0 && reflectance[band] < 1.0))
            throw RadiantError({"", where}, "reflectance band " + std::to_string(band) + " is " +
                                                std::to_string(reflectance[band]) + ", expected a value in [0, 1)");
        if (!(exitance[band] >= 0.0))
            throw RadiantError({"", where}, "exitance band " + std::to_string(band) + " is " +
                                                std::to_string(exitance[band]) + " W/m^2, expected >= 0");
    }
}

std::string surfaceLabel(std::size_t surface) { return "surface " + std::to_string(surface); }

} // namespace

PatchMaterials PatchMaterials::from(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays) {
    if (mesh.surfaceFirstPatch.size() != scene.surfaces.size() + 1 || mesh.surfaceFirstPatch.back() != mesh.size())
        throw RadiantError({scene.name, "patch mesh"},
                           "the mesh has " + std::to_string(mesh.surfaceFirstPatch.size()) +
                               " surface offsets for " + std::to_string(scene.surfaces.size()) +
                               " surfaces: it was not meshed from this scene");
    PatchMaterials materials;
    materials.surfaceFirstPatch = mesh.surfaceFirstPatch;
    materials.area.resize(mesh.size());
    materials.reflectance.resize(mesh.size());
    materials.exitance.resize(mesh.size());
    materials.source.resize(mesh.size());
    if (scene.lights.empty()) {
        materials.directIrradiance.assign(mesh.size(), Rgb(0.0));
    } else {
        std::optional<RayCaster> own;
        if (!rays) rays = &own.emplace(scene);
        materials.directIrradiance = meanDirectIrradiance(scene, mesh, rays);
    }
    for (std::size_t i = 0; i < mesh.size(); ++i) materials.area[i] = mesh.patches[i].area;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const std::size_t m = scene.surfaces[s].material;
        if (m >= scene.materials.size())
            throw RadiantError({scene.name, "surface '" + scene.surfaces[s].name + "'"},
                               "material index " + std::to_string(m) + " out of range (" +
                                   std::to_string(scene.materials.size()) + " materials)");
        materials.setSurface(s, scene.materials[m].reflectance, scene.materials[m].exitance);
    }
    return materials;
}

void PatchMaterials::setSurface(std::size_t surface, const Rgb& newReflectance, const ExitanceRgb& newExitance) {
    if (surface >= surfaceCount())
        throw RadiantError({"", surfaceLabel(surface)},
                           "no such surface (the scene has " + std::to_string(surfaceCount()) + ")");
    checkMaterial(surfaceLabel(surface), newReflectance, newExitance.value());
    for (std::size_t i = surfaceFirstPatch[surface]; i < surfaceFirstPatch[surface + 1]; ++i) {
        reflectance[i] = newReflectance;
        exitance[i] = newExitance.value();
        source[i] = exitance[i] + reflectance[i] * directIrradiance[i];
    }
}

Rgb PatchMaterials::emittedPower() const {
    Rgb sum(0.0);
    for (std::size_t i = 0; i < size(); ++i) sum += area[i] * source[i];
    return sum;
}

double fractionOfEmitted(const Rgb& power, const Rgb& emitted) {
    const double brightest = std::max({emitted.x, emitted.y, emitted.z});
    double worst = 0;
    for (int band = 0; band < 3; ++band) {
        const double reference = emitted[band] > 0 ? emitted[band] : brightest;
        worst = std::max(worst, reference > 0 ? power[band] / reference : power[band]);
    }
    return worst;
}

std::uint64_t pairSeed(std::uint64_t seed, std::size_t i, std::size_t j) {
    // SplitMix64's finaliser over the seed and both indices.
    std::uint64_t z = seed ^ (static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull) ^
                      (static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4Full);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

} // namespace radiant
