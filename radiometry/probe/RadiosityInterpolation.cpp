#include "radiometry/probe/RadiosityInterpolation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/probe/OpenFirstMean.h"

namespace radiant {

std::vector<Rgb> vertexRadiosity(const PatchMesh& mesh, std::span<const Rgb> patchRadiosity) {
    if (patchRadiosity.size() != mesh.patches.size())
        throw RadiantError({"", "radiosity interpolation"},
                           "the solution has " + std::to_string(patchRadiosity.size()) + " values for " +
                               std::to_string(mesh.patches.size()) + " patches");
    std::vector<OpenFirstMean> mean(mesh.vertices.size());
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        for (std::size_t c = 0; c < patch.cornerCount; ++c)
            mean[patch.corners[c]].add(patchRadiosity[p], patch.area, patch.covered);
    }
    std::vector<Rgb> value(mesh.vertices.size());
    for (std::size_t v = 0; v < value.size(); ++v) value[v] = mean[v].mean();
    return value;
}

std::array<double, 4> wachspressCoordinates(std::span<const glm::dvec3> corners, const glm::dvec3& normal,
                                            const glm::dvec3& point) {
    const std::size_t n = corners.size();
    std::array<double, 4> weights{};
    if (n < 3 || n > 4) return weights;
    // Signed doubled areas of (point, v_j, v_j+1), clamped so a point just outside lands on the border.
    std::array<double, 4> edgeArea{};
    for (std::size_t j = 0; j < n; ++j)
        edgeArea[j] = std::max(0.0, glm::dot(normal, glm::cross(corners[j] - point, corners[(j + 1) % n] - point)));
    // Product form w_i = C_i prod_{j != i-1, i} A_j: no division, so it stays finite on the border.
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& previous = corners[(i + n - 1) % n];
        const glm::dvec3& next = corners[(i + 1) % n];
        double w = glm::dot(normal, glm::cross(corners[i] - previous, next - previous));
        for (std::size_t j = 0; j < n; ++j)
            if (j != i && j != (i + n - 1) % n) w *= edgeArea[j];
        weights[i] = std::max(0.0, w);
        total += weights[i];
    }
    if (total > 0) {
        for (double& w : weights) w /= total;
        return weights;
    }
    // Degenerate (a point outside beyond a corner clamps every product to zero): take the nearest corner.
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < n; ++i)
        if (glm::length(corners[i] - point) < glm::length(corners[nearest] - point)) nearest = i;
    weights[nearest] = 1;
    return weights;
}

Rgb interpolateRadiosity(const PatchMesh& mesh, std::size_t patch, const glm::dvec3& point,
                         std::span<const Rgb> vertexValues) {
    const Patch& p = mesh.patches.at(patch);
    std::array<glm::dvec3, 4> corners{};
    for (std::size_t c = 0; c < p.cornerCount; ++c) corners[c] = mesh.vertices[p.corners[c]];
    const auto w = wachspressCoordinates(std::span(corners.data(), p.cornerCount), p.normal, point);
    Rgb value(0.0);
    for (std::size_t c = 0; c < p.cornerCount; ++c) value += w[c] * vertexValues[p.corners[c]];
    return value;
}

Rgb interpolateRadiosity(const PatchMesh& mesh, std::span<const Rgb> patchRadiosity, std::size_t patch,
                         const glm::dvec3& point) {
    if (patchRadiosity.size() != mesh.patches.size())
        throw RadiantError({"", "radiosity interpolation"},
                           "the solution has " + std::to_string(patchRadiosity.size()) + " values for " +
                               std::to_string(mesh.patches.size()) + " patches");
    const Patch& p = mesh.patches.at(patch);
    // Coplanar within a relative angle and offset tolerance: the faces of one wall may be split.
    constexpr double kCosTolerance = 1e-9;
    const double offsetTolerance = 1e-9 + 1e-6 * std::sqrt(p.area);
    std::array<OpenFirstMean, 4> mean{};
    for (std::uint32_t q = mesh.surfaceFirstPatch[p.surface]; q < mesh.surfaceFirstPatch[p.surface + 1]; ++q) {
        const Patch& other = mesh.patches[q];
        if (glm::dot(other.normal, p.normal) < 1.0 - kCosTolerance) continue;
        if (std::abs(glm::dot(p.normal, other.centroid - p.centroid)) > offsetTolerance) continue;
        for (std::size_t c = 0; c < p.cornerCount; ++c)
            for (std::size_t k = 0; k < other.cornerCount; ++k)
                if (other.corners[k] == p.corners[c]) mean[c].add(patchRadiosity[q], other.area, other.covered);
    }
    std::array<glm::dvec3, 4> corners{};
    for (std::size_t c = 0; c < p.cornerCount; ++c) corners[c] = mesh.vertices[p.corners[c]];
    const auto w = wachspressCoordinates(std::span(corners.data(), p.cornerCount), p.normal, point);
    Rgb value(0.0);
    for (std::size_t c = 0; c < p.cornerCount; ++c) value += w[c] * mean[c].mean();
    return value;
}

} // namespace radiant
