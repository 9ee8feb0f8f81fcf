#include "radiometry/probe/PolygonSamples.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace radiant {

std::uint64_t mixBits(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

void stratifiedPolygonSamples(const PatchPolygon& polygon, int perSide, std::uint64_t seed,
                              std::vector<PolygonSample>& out) {
    out.clear();
    if (perSide <= 0 || polygon.count < 3) return;
    const double cell = 1.0 / perSide;
    const double cellArea = cell * cell;
    std::uint64_t state = mixBits(seed);
    const auto jitter = [&state] {
        state = mixBits(state);
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    const glm::dvec3& v0 = polygon.vertices[0];
    const glm::dvec3& v1 = polygon.vertices[1];
    const glm::dvec3& v2 = polygon.vertices[2];
    const glm::dvec3& v3 = polygon.vertices[3];
    out.reserve(static_cast<std::size_t>(perSide) * static_cast<std::size_t>(perSide));
    for (int i = 0; i < perSide; ++i)
        for (int j = 0; j < perSide; ++j) {
            const double u = (i + jitter()) * cell;
            const double v = (j + jitter()) * cell;
            if (polygon.count == 3) {
                const double root = std::sqrt(u);
                out.push_back({(1 - root) * v0 + root * (1 - v) * v1 + root * v * v2, polygon.area * cellArea});
            } else {
                const glm::dvec3 point = (1 - u) * (1 - v) * v0 + u * (1 - v) * v1 + u * v * v2 + (1 - u) * v * v3;
                const glm::dvec3 du = (1 - v) * (v1 - v0) + v * (v2 - v3);
                const glm::dvec3 dv = (1 - u) * (v3 - v0) + u * (v2 - v1);
                out.push_back({point, glm::length(glm::cross(du, dv)) * cellArea});
            }
        }
}

} // namespace radiant
