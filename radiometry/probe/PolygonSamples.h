#pragma once
// Stratified, jittered points on a patch (triangle or convex quad), each carrying the area it stands
// for, so that sum(area_k g(p_k)) estimates the integral of g over the patch. Quads use the bilinear
// map (Jacobian as the area), triangles the square-root warp (area-uniform; Shirley & Chiu, "A
// Low Distortion Map Between Disk and Square", JGT 1997, for the idea of warping strata).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

struct PolygonSample {
    glm::dvec3 point{0.0};
    double area = 0;  ///< m^2 this sample stands for
};

/// perSide x perSide strata, one jittered point in each; deterministic for (polygon, seed). Replaces
/// the contents of `out` (kept as an argument so callers can reuse its storage).
void stratifiedPolygonSamples(const PatchPolygon& polygon, int perSide, std::uint64_t seed,
                              std::vector<PolygonSample>& out);

/// SplitMix64's finaliser (Steele, Lea & Flood, OOPSLA 2014): a well-mixed 64-bit hash, used to give
/// every patch its own reproducible jitter.
std::uint64_t mixBits(std::uint64_t z);

} // namespace radiant
