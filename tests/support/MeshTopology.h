#pragma once
// Topology checks of a PatchMesh for the meshing tests: sharing of vertices (Euler characteristic)
// and T-junctions, by vertex ids and positions, never by the mesher's own bookkeeping; and the
// one-surface scenes those tests mesh.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"

namespace radiant::test {

/// A face through these corners (counter-clockwise about its normal), its area and normal derived.
inline Face makeFace(std::vector<glm::dvec3> corners) {
    Face face;
    face.vertices = std::move(corners);
    face.updateGeometry();
    return face;
}
inline Face makeFace(std::initializer_list<glm::dvec3> corners) { return makeFace(std::vector<glm::dvec3>(corners)); }

/// One grey surface made of `faces`.
inline Scene sceneOf(std::vector<Face> faces) {
    Scene scene;
    scene.name = "test";
    scene.materials = {{"grey", Rgb{0.5}, ExitanceRgb{}}};
    scene.surfaces.push_back({"surface", 0, std::move(faces), "test"});
    return scene;
}

/// V - E + F of one surface's patches, counting vertex ids and undirected edges by vertex ids.
/// A duplicated seam vertex or a T-junction changes it, so it tests sharing, not just geometry.
inline long eulerCharacteristic(const PatchMesh& mesh, std::size_t surface) {
    std::set<std::uint32_t> vertices;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    const std::size_t first = mesh.surfaceFirstPatch[surface], last = mesh.surfaceFirstPatch[surface + 1];
    for (std::size_t p = first; p < last; ++p) {
        const Patch& patch = mesh.patches[p];
        for (std::size_t i = 0; i < patch.cornerCount; ++i) {
            const std::uint32_t a = patch.corners[i], b = patch.corners[(i + 1) % patch.cornerCount];
            vertices.insert(a);
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    }
    return static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) + static_cast<long>(last - first);
}

/// Vertices of the surface lying strictly inside a patch edge of the same surface (T-junctions).
inline std::size_t countTJunctions(const PatchMesh& mesh, std::size_t surface, double cell) {
    const std::size_t first = mesh.surfaceFirstPatch[surface], last = mesh.surfaceFirstPatch[surface + 1];
    std::set<std::uint32_t> used;
    for (std::size_t p = first; p < last; ++p)
        for (std::size_t i = 0; i < mesh.patches[p].cornerCount; ++i) used.insert(mesh.patches[p].corners[i]);
    const auto key = [cell](const glm::dvec3& v) {
        return std::tuple<long, long, long>{std::lround(std::floor(v.x / cell)), std::lround(std::floor(v.y / cell)),
                                            std::lround(std::floor(v.z / cell))};
    };
    std::map<std::tuple<long, long, long>, std::vector<std::uint32_t>> grid;
    for (std::uint32_t v : used) grid[key(mesh.vertices[v])].push_back(v);

    std::size_t found = 0;
    for (std::size_t p = first; p < last; ++p) {
        const Patch& patch = mesh.patches[p];
        for (std::size_t i = 0; i < patch.cornerCount; ++i) {
            const std::uint32_t ia = patch.corners[i], ib = patch.corners[(i + 1) % patch.cornerCount];
            const glm::dvec3 a = mesh.vertices[ia], b = mesh.vertices[ib];
            const auto [x0, y0, z0] = key(glm::min(a, b));
            const auto [x1, y1, z1] = key(glm::max(a, b));
            for (long x = x0 - 1; x <= x1 + 1; ++x)
                for (long y = y0 - 1; y <= y1 + 1; ++y)
                    for (long z = z0 - 1; z <= z1 + 1; ++z) {
                        const auto bucket = grid.find({x, y, z});
                        if (bucket == grid.end()) continue;
                        for (std::uint32_t v : bucket->second) {
                            if (v == ia || v == ib) continue;
                            const glm::dvec3 q = mesh.vertices[v];
                            const double t = glm::dot(q - a, b - a) / glm::dot(b - a, b - a);
                            if (t <= 1e-9 || t >= 1 - 1e-9) continue;
                            if (glm::distance(a + t * (b - a), q) < 1e-9) ++found;
                        }
                    }
        }
    }
    return found;
}

/// The summed area of surface `surface`'s patches (m^2).
inline double surfacePatchArea(const PatchMesh& mesh, std::size_t surface) {
    double sum = 0;
    for (std::size_t p = mesh.surfaceFirstPatch[surface]; p < mesh.surfaceFirstPatch[surface + 1]; ++p)
        sum += mesh.patches[p].area;
    return sum;
}

} // namespace radiant::test
