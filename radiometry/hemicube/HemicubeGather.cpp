#include "radiometry/hemicube/HemicubeGather.h"

#include <string>

#include "radiometry/common/Error.h"

namespace radiant {

HemicubeGatherResult gatherHemicube(const HemicubeLayout& layout, std::span<const std::uint32_t> items,
                                    const PatchMesh& mesh, std::size_t surfaceCount, std::span<const Rgb> radiosity) {
    if (items.size() != layout.pixelCount())
        throw RadiantError({"", "hemicube item buffer"}, std::to_string(items.size()) + " items for a " +
                                                             std::to_string(layout.width()) + " x " +
                                                             std::to_string(layout.height()) + " layout");
    if (!radiosity.empty() && radiosity.size() != mesh.size())
        throw RadiantError({"", "hemicube gather"}, std::to_string(radiosity.size()) + " radiosities for " +
                                                        std::to_string(mesh.size()) + " patches");
    HemicubeGatherResult result;
    result.surfaces.resize(surfaceCount);
    const std::vector<double>& dF = layout.deltaFormFactors();
    const std::vector<double>& dOmega = layout.solidAngles();
    // Per patch first (one add per pixel), then per surface: the patch sums feed E too.
    std::vector<double> patchFormFactor(mesh.size(), 0.0);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::uint32_t item = items[i];
        result.totalFormFactor += dF[i];
        if (item == kHemicubeEmpty) {
            result.openFormFactor += dF[i];
            continue;
        }
        const std::size_t patch = hemicubeItemPatch(item);
        if (patch >= mesh.size())
            throw RadiantError({"", "hemicube pixel " + std::to_string(i)},
                               "item names patch " + std::to_string(patch) + " of " + std::to_string(mesh.size()));
        const std::size_t surface = mesh.patches[patch].surface;
        if (surface >= surfaceCount)
            throw RadiantError({"", "patch " + std::to_string(patch)},
                               "surface " + std::to_string(surface) + " of " + std::to_string(surfaceCount));
        HemicubeSurfaceReading& reading = result.surfaces[surface];
        reading.solidAngle += SolidAngle(dOmega[i]);
        ++reading.pixels;
        if (hemicubeItemIsFront(item))
            patchFormFactor[patch] += dF[i];
        else
            result.backFaceFormFactor += dF[i];
    }
    Rgb irradiance{0.0};
    for (std::size_t patch = 0; patch < mesh.size(); ++patch) {
        if (patchFormFactor[patch] == 0) continue;
        result.surfaces[mesh.patches[patch].surface].formFactor += patchFormFactor[patch];
        if (!radiosity.empty()) irradiance += radiosity[patch] * patchFormFactor[patch];
    }
    result.irradiance = IrradianceRgb(irradiance);
    return result;
}

} // namespace radiant
