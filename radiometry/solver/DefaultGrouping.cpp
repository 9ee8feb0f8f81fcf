#include "radiometry/solver/DefaultGrouping.h"

#include "radiometry/common/PatchAreaText.h"
#include "radiometry/common/Thousands.h"
#include "radiometry/solver/Solver.h"

namespace radiant {
namespace {

std::string patchesInGroups(const PatchMesh& mesh, const PatchGroups& groups) {
    return withThousands(mesh.size()) + " patches in " + withThousands(groups.size()) + " groups";
}

MethodChoice namedOr(std::optional<SolverMethod> named, MethodChoice byDefault) {
    return named ? MethodChoice{*named, ""} : byDefault;
}

} // namespace

bool methodTakesGroups(SolverMethod method) {
    return method == SolverMethod::Jacobi || method == SolverMethod::GaussSeidel || method == SolverMethod::Progressive;
}

SystemChoice chooseSystem(const PatchMesh& mesh, double maxPatchArea, GroupingMode mode, std::optional<SolverMethod> named) {
    SystemChoice choice;
    const auto ungrouped = [&](std::string reason) {
        choice.groupingReason = std::move(reason);
        choice.method = namedOr(named, chooseDefaultMethod(mesh.size()));
        return choice;
    };
    if (mode == GroupingMode::Off) return ungrouped("off, as asked: every patch is an unknown");

    GroupingOptions options;
    options.maxGroupArea = maxPatchArea;
    if (mode == GroupingMode::Auto) {
        options.keepAtMostFraction = kGroupWhereAtMost;
        options.minimumFaces = kMinimumFacesToGroup;
    }
    auto groups = std::make_shared<const PatchGroups>(groupPatches(mesh, options));
    if (groups->size() == mesh.size())
        return ungrouped(mode == GroupingMode::On
                             ? "off: no two patches fit one group of " + patchAreaText(maxPatchArea)
                             : "off: no surface is tessellated finer than " + patchAreaText(maxPatchArea) +
                                   " (grouped where a surface's 16 or more faces average at most half of it and "
                                   "grouping at least halves its patches)");
    if (named && !methodTakesGroups(*named)) {
        choice.methodTakesNoGroups = true;
        return ungrouped("off: " + std::string(methodName(*named)) + " refines its own elements and takes no groups (" +
                         patchesInGroups(mesh, *groups) + " otherwise)");
    }
    if (mode == GroupingMode::Auto && !named && groups->size() > kProgressiveMaxPatches)
        return ungrouped("off: " + patchesInGroups(mesh, *groups) + " would be more than " +
                         withThousands(kProgressiveMaxPatches) +
                         " unknowns, where hierarchical radiosity over the patches is faster; it takes no groups");

    std::size_t surfaces = 0, grouped = 0;
    for (std::size_t s = 0; s + 1 < groups->surfaceFirstGroup.size(); ++s) {
        ++surfaces;
        grouped += groups->surfaceFirstGroup[s + 1] - groups->surfaceFirstGroup[s] <
                   mesh.surfaceFirstPatch[s + 1] - mesh.surfaceFirstPatch[s];
    }
    choice.groupingReason = "on" + std::string(mode == GroupingMode::On ? ", as asked" : "") + ": " +
                            patchesInGroups(mesh, *groups) + " (" + std::to_string(grouped) + " of " +
                            std::to_string(surfaces) + " surfaces tessellated finer than " + patchAreaText(maxPatchArea) +
                            ", grouped to about it)";
    choice.method = namedOr(named, chooseDefaultMethodForGroups(groups->size(), mesh.size()));
    choice.groups = std::move(groups);
    return choice;
}

} // namespace radiant
