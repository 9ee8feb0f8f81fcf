#include "render/display/SmoothingGroups.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "radiometry/probe/OpenFirstMean.h"

namespace radiant::render {

SmoothingGroups findSmoothingGroups(const PatchMesh& mesh, double maxAngleDegrees) {
    const double minCosine = std::cos(maxAngleDegrees * std::numbers::pi / 180.0);
    struct Group {
        glm::dvec3 normal;
        std::uint32_t id;
    };
    // Groups per mesh vertex: a handful at most (a vertex on a crease, or where faces of one
    // surface meet at an angle), so a linear scan.
    std::vector<std::vector<Group>> groupsAt(mesh.vertices.size());
    SmoothingGroups result;
    result.cornerVertex.assign(mesh.patches.size(), {});
    result.cornerCount.resize(mesh.patches.size());
    result.covered.resize(mesh.patches.size());
    std::uint32_t next = 0;
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        result.cornerCount[p] = patch.cornerCount;
        result.covered[p] = patch.covered ? 1 : 0;
        for (std::uint8_t c = 0; c < patch.cornerCount; ++c) {
            std::vector<Group>& groups = groupsAt[patch.corners[c]];
            std::uint32_t id = next;
            for (const Group& group : groups)
                if (glm::dot(group.normal, patch.normal) >= minCosine) {
                    id = group.id;
                    break;
                }
            if (id == next) groups.push_back({patch.normal, next++});
            result.cornerVertex[p][c] = id;
        }
    }
    result.vertexCount = next;
    return result;
}

void smoothRadiosity(const SmoothingGroups& groups, std::span<const double> patchAreaM2,
                     std::span<const Rgb> radiosityW_m2, std::vector<Rgb>& out) {
    // Groups made by hand in tests may leave `covered` empty: every patch open.
    std::vector<OpenFirstMean> mean(groups.vertexCount);
    for (std::size_t p = 0; p < radiosityW_m2.size(); ++p) {
        const bool covered = p < groups.covered.size() && groups.covered[p];
        for (std::uint8_t c = 0; c < groups.cornerCount[p]; ++c)
            mean[groups.cornerVertex[p][c]].add(radiosityW_m2[p], patchAreaM2[p], covered);
    }
    out.resize(groups.vertexCount);
    for (std::size_t v = 0; v < out.size(); ++v) out[v] = mean[v].mean();
}

} // namespace radiant::render
