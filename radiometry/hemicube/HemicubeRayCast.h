#pragma once
// The hemicube's item buffer made by casting one ray through each pixel centre instead of
// rasterising: the same sampling of the hemisphere as the GPU renderer (Cohen & Greenberg 1985),
// with Embree resolving visibility. A reference for tests and a route that needs no GL context.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/hemicube/HemicubeLayout.h"
#include "radiometry/mesh/PatchLocator.h"

namespace radiant {

/// Items (HemicubeGather.h encoding) for a hemicube at x about the unit normal n.
std::vector<std::uint32_t> castHemicube(const HemicubeLayout& layout, const RayCaster& rays,
                                        const PatchLocator& patches, const glm::dvec3& x, const glm::dvec3& n);

} // namespace radiant
