#include "radiometry/solver/OpeningPatchArea.h"

#include <cmath>
#include <cstddef>
#include <cstdio>

#include "radiometry/common/PatchAreaText.h"
#include "radiometry/common/Thousands.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/SolveDefaults.h"

namespace radiant {
namespace {

/// A scene's total area to three digits ("57.5 m^2"), in the reason only.
std::string sceneAreaText(double area) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g m^2", area);
    return text;
}

std::size_t patchesAt(const Scene& scene, double area) {
    MeshingOptions meshing;
    meshing.maxPatchArea = area;
    return estimatePatchCount(scene, meshing);
}

} // namespace

OpeningArea openingPatchArea(const Scene& scene) {
    const double base = kSolveDefaults.maxPatchArea;
    const std::size_t budget = kProgressiveMaxPatches;
    const std::size_t atBase = patchesAt(scene, base);
    if (atBase <= budget)
        return {base, inSquareCentimetres(base) + ", the default: " + withThousands(atBase) + " patches (a scene of more than " +
                          withThousands(budget) + " opens coarser)"};
    // Steps in cm^2 from the default's decade: 1, 2, 2.5, 5, 10, 20, 25, 50, ...
    const double decade = std::pow(10.0, std::floor(std::log10(base * kCm2PerM2) + 1e-9));
    double chosen = kMaxOpeningPatchArea;
    std::size_t patches = 0;
    for (double scale = decade; scale / kCm2PerM2 < kMaxOpeningPatchArea; scale *= 10) {
        bool found = false;
        for (const double step : {1.0, 2.0, 2.5, 5.0}) {
            const double area = step * scale / kCm2PerM2;
            if (area <= base || area >= kMaxOpeningPatchArea) continue;
            patches = patchesAt(scene, area);
            if (patches <= budget) {
                chosen = area;
                found = true;
                break;
            }
        }
        if (found) break;
    }
    if (chosen == kMaxOpeningPatchArea) patches = patchesAt(scene, chosen);
    return {chosen, inSquareCentimetres(chosen) + " for the scene's " + sceneAreaText(scene.totalArea()) + ": " + withThousands(patches) +
                        " patches, within the " + withThousands(budget) + " progressive refinement solves by default (" + inSquareCentimetres(base) + " would make " +
                        withThousands(atBase) + ")"};
}

} // namespace radiant
