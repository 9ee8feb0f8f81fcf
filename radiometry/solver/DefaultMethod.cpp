#include "radiometry/solver/DefaultMethod.h"

#include <cstddef>

#include "radiometry/common/Thousands.h"
#include "radiometry/solver/SolveDefaults.h"

namespace radiant {

// The reasons below describe progressive refinement; a different small-mesh default needs its own.
static_assert(kSolveDefaults.method == SolverMethod::Progressive);

MethodChoice chooseDefaultMethod(std::size_t patches) {
    const std::string count = withThousands(patches) + " patches: ";
    const std::string limit = withThousands(kProgressiveMaxPatches);
    if (patches > kProgressiveMaxPatches)
        return {SolverMethod::Hierarchical,
                count + "progressive refinement's time grows faster than the patch count (4.6 s at 10,000 in the "
                        "Cornell box, hierarchical 3.4 s); hierarchical above " + limit + " patches"};
    // Not "the fastest": on the Cornell box hierarchical converges in about a quarter of its time
    // (README, the accuracy table); progressive's steps show the light spreading a patch at a time.
    return {kSolveDefaults.method, count + "progressive refinement, within 1% of the path tracer, each step one "
                                           "patch shooting its light; hierarchical above " + limit + " patches"};
}

MethodChoice chooseDefaultMethodForGroups(std::size_t groups, std::size_t patches) {
    const std::string count = withThousands(patches) + " patches in " + withThousands(groups) + " groups: ";
    const std::string limit = withThousands(kProgressiveMaxPatches);
    if (groups > kProgressiveMaxPatches)
        return {SolverMethod::Progressive, count + "progressive refinement over the groups; hierarchical, faster above " +
                                               limit + " unknowns, takes no groups"};
    return {SolverMethod::Progressive, count + "progressive refinement over the groups, the unknowns; hierarchical, "
                                               "for more than " + limit + ", takes no groups"};
}

MethodChoice chooseDefaultMethod(const Scene& scene, const MeshingOptions& meshing) {
    return chooseDefaultMethod(estimatePatchCount(scene, meshing));
}

} // namespace radiant
