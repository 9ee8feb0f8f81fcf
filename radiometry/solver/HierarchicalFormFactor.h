#pragma once
// The form-factor estimates behind every link, written for the inner loop of refinement: fixed-size
// arrays, no allocation, inlined. The point-to-polygon kernel is Lambert's exact contour integral
//   F(dx -> P) = 1/(2 pi) sum_i gamma_i n . (R_{i+1} x R_i) / |R_{i+1} x R_i|
// (for P counter-clockwise seen from its front), after clipping P to the half-space above x's
// tangent plane (Sutherland-Hodgman), as in radiometry/formfactor but specialised to the 3- and
// 4-corner polygons of the element tree.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant::hierarchical {

/// Exact unoccluded F from a differential area at x (unit normal n) to `polygon`; 0 when x sees the
/// polygon's back or nothing of it lies above x's tangent plane.
inline double pointToElementFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& polygon) {
    if (glm::dot(polygon.normal, x - polygon.centroid) <= 0) return 0;  // behind the emitting side
    std::array<glm::dvec3, 5> clipped;  // a convex polygon clipped by a plane gains at most one corner
    int count = 0;
    const int corners = polygon.count;
    std::array<double, 4> height{};
    bool allAbove = true;
    for (int i = 0; i < corners; ++i) {
        height[static_cast<std::size_t>(i)] = glm::dot(n, polygon.vertices[static_cast<std::size_t>(i)] - x);
        allAbove = allAbove && height[static_cast<std::size_t>(i)] >= 0;
    }
    if (allAbove) {
        for (int i = 0; i < corners; ++i)
            clipped[static_cast<std::size_t>(i)] = polygon.vertices[static_cast<std::size_t>(i)] - x;
        count = corners;
    } else {
        for (int i = 0; i < corners; ++i) {
            const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>((i + 1) % corners);
            if (height[a] >= 0) clipped[static_cast<std::size_t>(count++)] = polygon.vertices[a] - x;
            if ((height[a] >= 0) != (height[b] >= 0)) {
                const double t = height[a] / (height[a] - height[b]);
                clipped[static_cast<std::size_t>(count++)] =
                    polygon.vertices[a] + t * (polygon.vertices[b] - polygon.vertices[a]) - x;
            }
        }
        if (count < 3) return 0;
    }
    double sum = 0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3& r0 = clipped[static_cast<std::size_t>(i)];
        const glm::dvec3& r1 = clipped[static_cast<std::size_t>((i + 1) % count)];
        const glm::dvec3 c = glm::cross(r1, r0);
        const double length = glm::length(c);
        if (length <= 0) continue;  // x on this edge's line: the edge subtends no angle
        // atan2 of |sin| and cos keeps gamma accurate for nearly parallel R_i (acos does not).
        const double gamma = std::atan2(length, glm::dot(r0, r1));
        sum += gamma * glm::dot(n, c) / length;
    }
    return std::max(0.0, sum / (2 * std::numbers::pi));
}

/// Squared distance over source area beyond which farFieldFormFactor stands in for the exact kernel:
/// there the source subtends under 1% of pi sr's worth (A / (pi r^2) < 0.01).
inline constexpr double kFarFieldDistanceSquaredOverArea = 32;

/// F from a differential area at x (unit normal n) to a source small against its distance, by the
/// disk approximation A cos(theta_x) cos(theta_q) / (pi r^2 + A) (J. Wallace, K. Elmquist,
/// E. Haines, "A ray tracing algorithm for progressive radiosity", SIGGRAPH 1989), exact for a
/// coaxial disk and within a fraction of a percent of the exact kernel when r^2 > 32 A and the
/// source lies wholly above x's tangent plane. Returns a negative value when some corner of the
/// source is below that plane: the caller must then clip, i.e. use pointToElementFormFactor.
inline double farFieldFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source) {
    for (int i = 0; i < source.count; ++i)
        if (glm::dot(n, source.vertices[static_cast<std::size_t>(i)] - x) <= 0) return -1;
    const glm::dvec3 d = source.centroid - x;
    const double r2 = glm::dot(d, d);
    const double cosReceiver = glm::dot(n, d);          // times r
    const double cosSource = -glm::dot(source.normal, d);  // times r
    if (cosSource <= 0) return 0;
    return source.area * cosReceiver * cosSource / (r2 * (std::numbers::pi * r2 + source.area));
}

/// The exact kernel, or the far-field estimate where it is safe (`far`: the pair is far apart for the
/// source's size).
inline double pointToElementFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source,
                                       bool far) {
    if (far) {
        const double estimate = farFieldFormFactor(x, n, source);
        if (estimate >= 0) return estimate;
    }
    return pointToElementFormFactor(x, n, source);
}

/// The centroids of the four children the element would split into: a 4-point rule over it whose
/// points are exactly where its children will evaluate.
inline std::array<glm::dvec3, 4> childCentroids(const PatchPolygon& p) {
    const auto& v = p.vertices;
    if (p.count == 4) {
        const auto at = [&](double u, double w) {
            return (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
        };
        return {at(0.25, 0.25), at(0.75, 0.25), at(0.75, 0.75), at(0.25, 0.75)};
    }
    return {(4.0 * v[0] + v[1] + v[2]) / 6.0, (v[0] + 4.0 * v[1] + v[2]) / 6.0, (v[0] + v[1] + 4.0 * v[2]) / 6.0,
            (v[0] + v[1] + v[2]) / 3.0};
}

/// The receiver's mean of the exact kernel to `source`, F(receiver -> source) unoccluded, by a 3 x 3
/// Gauss-Legendre rule over the receiver (bilinear map on a quad, the collapsed Duffy map on a
/// triangle, each weighted by its Jacobian). For elements sharing an edge, where the kernel changes
/// like x log x, it is within 3e-5 of the catalog's 0.200044 for unit squares; the 2 x 2 midpoint
/// rule is 1% low there.
inline double gaussMeanKernel(const PatchPolygon& receiver, const PatchPolygon& source) {
    static constexpr std::array<double, 3> node{0.1127016653792583, 0.5, 0.8872983346207417};
    static constexpr std::array<double, 3> weight{5.0 / 18, 8.0 / 18, 5.0 / 18};
    const auto& v = receiver.vertices;
    double sum = 0, weights = 0;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            const double u = node[i], w = node[k];
            glm::dvec3 x, du, dw;
            if (receiver.count == 4) {
                x = (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
                du = (1 - w) * (v[1] - v[0]) + w * (v[2] - v[3]);
                dw = (1 - u) * (v[3] - v[0]) + u * (v[2] - v[1]);
            } else {
                x = v[0] + u * (v[1] - v[0]) + u * w * (v[2] - v[1]);
                du = (v[1] - v[0]) + w * (v[2] - v[1]);
                dw = u * (v[2] - v[1]);
            }
            const double jacobian = weight[i] * weight[k] * glm::length(glm::cross(du, dw));
            sum += jacobian * pointToElementFormFactor(x, receiver.normal, source);
            weights += jacobian;
        }
    return weights > 0 ? sum / weights : 0;
}

/// True when some of each element lies strictly in front of the other: otherwise no light passes.
inline bool facing(const PatchPolygon& a, const PatchPolygon& b) {
    const auto someInFront = [](const PatchPolygon& of, const PatchPolygon& plane) {
        const double tolerance = 1e-9 * std::sqrt(plane.area + of.area);
        for (const glm::dvec3& v : of.corners())
            if (glm::dot(plane.normal, v - plane.centroid) > tolerance) return true;
        return false;
    };
    return someInFront(a, b) && someInFront(b, a);
}

/// SplitMix64: a deterministic, well-mixed hash for the stratified jitter.
inline std::uint64_t mix(std::uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
inline double unitInterval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

/// A point of the polygon for (u, v) in the unit square: bilinear on a quad, the square-root warp on
/// a triangle (both area-uniform for the elements' parallelogram-like quads and all triangles).
inline glm::dvec3 pointOn(const PatchPolygon& p, double u, double v) {
    const auto& c = p.vertices;
    if (p.count == 4) return (1 - v) * ((1 - u) * c[0] + u * c[1]) + v * ((1 - u) * c[3] + u * c[2]);
    const double s = std::sqrt(u);
    return (1 - s) * c[0] + s * (1 - v) * c[1] + s * v * c[2];
}

/// Fraction of `rays` stratified segments between the two elements that nothing blocks. The
/// samples are pulled slightly inside each element so that no ray starts on a shared edge.
inline double elementVisibility(const PatchPolygon& a, const PatchPolygon& b, const RayCaster& caster, int rays,
                                std::uint64_t seed) {
    if (rays <= 0) return 1;
    int unblocked = 0;
    for (int k = 0; k < rays; ++k) {
        const std::uint64_t h1 = mix(seed + static_cast<std::uint64_t>(k) * 4 + 0);
        const std::uint64_t h2 = mix(seed + static_cast<std::uint64_t>(k) * 4 + 1);
        const std::uint64_t h3 = mix(seed + static_cast<std::uint64_t>(k) * 4 + 2);
        const std::uint64_t h4 = mix(seed + static_cast<std::uint64_t>(k) * 4 + 3);
        // Latin-hypercube strata: row k, column (3k + 1) mod rays, on each element independently.
        const double n = rays;
        const double inset = 0.02;  // keep samples off the element's edges
        const auto stratum = [&](int i, std::uint64_t bits) {
            return inset + (1 - 2 * inset) * ((i + unitInterval(bits)) / n);
        };
        const glm::dvec3 pa = pointOn(a, stratum(k, h1), stratum((3 * k + 1) % rays, h2));
        const glm::dvec3 pb = pointOn(b, stratum((k + 1) % rays, h3), stratum((3 * k + 2) % rays, h4));
        if (!caster.occluded(pa, pb)) ++unblocked;
    }
    return static_cast<double>(unblocked) / rays;
}

} // namespace radiant::hierarchical
