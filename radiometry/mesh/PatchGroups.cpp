#include "radiometry/mesh/PatchGroups.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <numbers>
#include <queue>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

void checkPositive(double value, const char* what) {
    if (!(value > 0) || !std::isfinite(value))
        throw RadiantError({"", "patch grouping"}, std::string(what) + " must be positive and finite, got " + std::to_string(value));
}

/// Edge-adjacent patches of one surface without a crease between them, as local indices. The mesh
/// is conforming within a surface, so neighbours share an edge's two vertex indices.
std::vector<std::vector<std::uint32_t>> smoothNeighbours(const PatchMesh& mesh, std::uint32_t first, std::uint32_t last,
                                                         double cosCrease) {
    std::vector<std::vector<std::uint32_t>> neighbours(last - first);
    std::unordered_map<std::uint64_t, std::uint32_t> owner;
    owner.reserve(2 * static_cast<std::size_t>(last - first));
    for (std::uint32_t p = first; p < last; ++p) {
        const Patch& patch = mesh.patches[p];
        for (std::uint8_t k = 0; k < patch.cornerCount; ++k) {
            const std::uint32_t a = patch.corners[k], b = patch.corners[(k + 1) % patch.cornerCount];
            const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
            const auto [it, inserted] = owner.try_emplace(key, p);
            if (inserted) continue;
            const std::uint32_t q = it->second;
            if (glm::dot(patch.normal, mesh.patches[q].normal) < cosCrease) continue;
            neighbours[p - first].push_back(q - first);
            neighbours[q - first].push_back(p - first);
        }
    }
    return neighbours;
}

} // namespace

PatchGroups groupPatches(const PatchMesh& mesh, const GroupingOptions& options) {
    checkPositive(options.maxGroupArea, "the maximum group area");
    checkPositive(options.creaseDegrees, "the crease angle");
    checkPositive(options.spreadDegrees, "the normal spread");
    if (!(options.keepAtMostFraction > 0 && options.keepAtMostFraction <= 1))
        throw RadiantError({"", "patch grouping"}, "the fraction of groups kept must be in (0, 1], got " +
                                                     std::to_string(options.keepAtMostFraction));
    const double degree = std::numbers::pi / 180;
    const double cosCrease = std::cos(options.creaseDegrees * degree), cosSpread = std::cos(options.spreadDegrees * degree);
    // The mesher's patches are at most the requested area up to a relative 4e-6 (MeshingOptions).
    const double areaLimit = options.maxGroupArea * (1 + 1e-5);

    PatchGroups groups;
    groups.groupOf.assign(mesh.size(), kNone);
    groups.firstMember.push_back(0);
    const std::size_t surfaces = mesh.surfaceFirstPatch.empty() ? 0 : mesh.surfaceFirstPatch.size() - 1;
    struct Grown {
        std::vector<std::uint32_t> patches;  // global indices
        double area = 0;
        glm::dvec3 normalSum{0.0};  // area-weighted
    };
    const auto keepPatches = [&](std::uint32_t first, std::uint32_t last) {
        for (std::uint32_t p = first; p < last; ++p) {
            groups.groupOf[p] = static_cast<std::uint32_t>(groups.size());
            groups.members.push_back(p);
            groups.firstMember.push_back(static_cast<std::uint32_t>(groups.members.size()));
            groups.area.push_back(mesh.patches[p].area);
        }
    };
    for (std::size_t s = 0; s < surfaces; ++s) {
        groups.surfaceFirstGroup.push_back(static_cast<std::uint32_t>(groups.size()));
        const std::uint32_t first = mesh.surfaceFirstPatch[s], last = mesh.surfaceFirstPatch[s + 1];
        const double keepAtMost = options.keepAtMostFraction * (last - first);
        // Only a surface whose faces are smaller than the request: the mesher cuts a large face
        // to it, into patches that may be small where it cut along another face (the Cornell box's
        // floor around the blocks), and those stay patches.
        double surfaceArea = 0;
        std::uint32_t faces = 0;
        for (std::uint32_t p = first; p < last; ++p) {
            surfaceArea += mesh.patches[p].area;
            faces = std::max(faces, mesh.patches[p].face + 1);
        }
        if (faces < options.minimumFaces ||
            (options.keepAtMostFraction < 1 && surfaceArea > options.keepAtMostFraction * areaLimit * faces)) {
            keepPatches(first, last);
            continue;
        }
        const auto neighbours = smoothNeighbours(mesh, first, last, cosCrease);
        std::vector<std::uint32_t> groupOf(last - first, kNone);  // local patch -> local group
        std::vector<Grown> grown;
        const auto add = [&](Grown& group, std::uint32_t p) {
            group.patches.push_back(p);
            group.area += mesh.patches[p].area;
            group.normalSum += mesh.patches[p].area * mesh.patches[p].normal;
        };

        // Growth: a seed takes its nearest smooth neighbours while they fit the area and face within
        // the spread of the seed. What does not fit seeds the next group, beside this one.
        std::deque<std::uint32_t> seeds;  // local indices
        for (std::uint32_t start = 0; start < last - first; ++start) {
            seeds.push_back(start);
            while (!seeds.empty()) {
                const std::uint32_t seed = seeds.front();
                seeds.pop_front();
                if (groupOf[seed] != kNone) continue;
                const auto group = static_cast<std::uint32_t>(grown.size());
                const Patch& seedPatch = mesh.patches[seed + first];
                // Nearest to the seed first, so a group grows as a disc, not a strip.
                using Candidate = std::pair<double, std::uint32_t>;
                std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> frontier;
                const auto offer = [&](std::uint32_t local) {
                    if (groupOf[local] == kNone)
                        frontier.emplace(glm::distance(mesh.patches[local + first].centroid, seedPatch.centroid), local);
                };
                grown.emplace_back();
                groupOf[seed] = group;
                add(grown.back(), seed + first);
                for (const std::uint32_t q : neighbours[seed]) offer(q);
                while (!frontier.empty()) {
                    const std::uint32_t local = frontier.top().second;
                    frontier.pop();
                    if (groupOf[local] != kNone) continue;
                    const Patch& patch = mesh.patches[local + first];
                    if (grown.back().area + patch.area > areaLimit || glm::dot(patch.normal, seedPatch.normal) < cosSpread) {
                        seeds.push_back(local);
                        continue;
                    }
                    groupOf[local] = group;
                    add(grown.back(), local + first);
                    for (const std::uint32_t q : neighbours[local]) offer(q);
                }
            }
        }

        // Merging: growth leaves slivers where groups met. The smallest group first joins its
        // smallest smooth neighbour while the two fit the area and every patch of both faces within
        // the spread of their joint mean normal.
        std::vector<std::uint32_t> parent(grown.size());
        std::iota(parent.begin(), parent.end(), 0u);
        const auto find = [&](std::uint32_t g) {
            while (parent[g] != g) g = parent[g] = parent[parent[g]];
            return g;
        };
        using Sized = std::pair<double, std::uint32_t>;
        std::priority_queue<Sized, std::vector<Sized>, std::greater<>> smallest;
        for (std::uint32_t g = 0; g < grown.size(); ++g) smallest.emplace(grown[g].area, g);
        std::vector<std::uint32_t> candidates;
        const auto withinSpread = [&](const Grown& a, const Grown& b) {
            const glm::dvec3 mean = glm::normalize(a.normalSum + b.normalSum);
            for (const Grown* group : {&a, &b})
                for (const std::uint32_t p : group->patches)
                    if (glm::dot(mesh.patches[p].normal, mean) < cosSpread) return false;
            return true;
        };
        while (!smallest.empty()) {
            const auto [area, g] = smallest.top();
            smallest.pop();
            if (find(g) != g || area != grown[g].area) continue;  // merged, or queued again since
            candidates.clear();
            for (const std::uint32_t p : grown[g].patches)
                for (const std::uint32_t q : neighbours[p - first]) {
                    const std::uint32_t h = find(groupOf[q]);
                    if (h != g && area + grown[h].area <= areaLimit) candidates.push_back(h);
                }
            std::sort(candidates.begin(), candidates.end(), [&](std::uint32_t a, std::uint32_t b) {
                return grown[a].area != grown[b].area ? grown[a].area < grown[b].area : a < b;
            });
            candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
            for (const std::uint32_t h : candidates) {
                if (!withinSpread(grown[g], grown[h])) continue;
                parent[g] = h;
                for (const std::uint32_t p : grown[g].patches) add(grown[h], p);
                grown[g] = {};
                smallest.emplace(grown[h].area, h);
                break;
            }
        }

        std::size_t kept = 0;
        for (std::uint32_t g = 0; g < grown.size(); ++g) kept += find(g) == g;
        if (static_cast<double>(kept) > keepAtMost) {
            keepPatches(first, last);
            continue;
        }
        for (std::uint32_t g = 0; g < grown.size(); ++g) {
            if (find(g) != g) continue;
            std::vector<std::uint32_t>& patches = grown[g].patches;
            std::sort(patches.begin(), patches.end());
            const auto group = static_cast<std::uint32_t>(groups.size());
            for (const std::uint32_t p : patches) groups.groupOf[p] = group;
            groups.members.insert(groups.members.end(), patches.begin(), patches.end());
            groups.firstMember.push_back(static_cast<std::uint32_t>(groups.members.size()));
            double area = 0;  // summed in patch order, so it does not depend on the merges
            for (const std::uint32_t p : patches) area += mesh.patches[p].area;
            groups.area.push_back(area);
        }
    }
    groups.surfaceFirstGroup.push_back(static_cast<std::uint32_t>(groups.size()));
    return groups;
}

PatchGroups ungroupedPatches(const PatchMesh& mesh) {
    PatchGroups groups;
    const std::size_t n = mesh.size();
    groups.groupOf.resize(n);
    groups.members.resize(n);
    groups.firstMember.resize(n + 1);
    groups.area.resize(n);
    for (std::uint32_t p = 0; p < n; ++p) {
        groups.groupOf[p] = groups.members[p] = groups.firstMember[p] = p;
        groups.area[p] = mesh.patches[p].area;
    }
    groups.firstMember[n] = static_cast<std::uint32_t>(n);
    groups.surfaceFirstGroup.assign(mesh.surfaceFirstPatch.begin(), mesh.surfaceFirstPatch.end());
    return groups;
}

} // namespace radiant
