#include "radiometry/solver/DefaultMethod.h"

#include <cstddef>
#include <cstdio>

#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "radiometry/solver/SolveDefaults.h"

namespace radiant {

namespace {

/// 12345 -> "12,345": patch counts as people read them.
std::string withThousands(std::size_t n) {
    std::string digits = std::to_string(n);
    for (auto i = static_cast<std::ptrdiff_t>(digits.size()) - 3; i > 0; i -= 3)
        digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

std::string bytesText(double bytes) {
    char text[32];
    if (bytes >= 1e9)
        std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    else if (bytes >= 1e6)
        std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
    else
        std::snprintf(text, sizeof text, "%.0f kB", bytes / 1e3);
    return text;
}

} // namespace

MethodChoice chooseDefaultMethod(std::size_t patches, double matrixBudgetBytes) {
    const SolverMethod matrixMethod = kSolveDefaults.method;
    const std::string matrixLabel(methodInfo(matrixMethod).label);
    const double bytes = formFactorMatrixPeakBytes(patches);
    const std::string count = withThousands(patches) + " patches: ";
    if (bytes > matrixBudgetBytes)
        return {SolverMethod::Hierarchical, count + "a " + matrixLabel + " matrix would need up to " + bytesText(bytes) +
                                                ", over the budget of " + bytesText(matrixBudgetBytes)};
    if (patches > kMatrixMethodMaxPatches)
        return {SolverMethod::Hierarchical, count + "a " + matrixLabel + " matrix would need up to " + bytesText(bytes) +
                                                ", its form factors' time growing as patches squared; hierarchical above " +
                                                withThousands(kMatrixMethodMaxPatches) + " patches"};
    return {matrixMethod, count + "the " + matrixLabel + " matrix needs up to " + bytesText(bytes) +
                              "; hierarchical above " + withThousands(kMatrixMethodMaxPatches) + " patches"};
}

MethodChoice chooseDefaultMethod(const Scene& scene, const MeshingOptions& meshing, double matrixBudgetBytes) {
    return chooseDefaultMethod(estimatePatchCount(scene, meshing), matrixBudgetBytes);
}

} // namespace radiant
