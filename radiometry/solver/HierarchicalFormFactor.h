#pragma once
// The form-factor estimates behind every link, written for the inner loop of refinement: fixed-size
// arrays, no allocation, inlined. The point-to-polygon kernel is Lambert's exact contour integral
//   F(dx -> P) = 1/(2 pi) sum_i gamma_i n . (R_{i+1} x R_i) / |R_{i+1} x R_i|
// (for P counter-clockwise seen from its front), after clipping P to the half-space above x's
// tangent plane (Sutherland-Hodgman), as in radiometry/formfactor but specialised to the 3- and
// 4-corner polygons of the element tree.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant::hierarchical {

/// atan2(y, x) for y >= 0 (not both zero): Cephes' atan (S. L. Moshier, range reduction by tan(pi/8)
/// and tan(3 pi/8), a 4/5 rational in t^2), within 5e-16 of std::atan2 on 20M random pairs over 12
/// decades (scratch check), at about half its cost: glibc's correctly rounded atan2 was a tenth of the
/// hierarchical solve's CPU.
inline double angleOf(double y, double x) {
    constexpr double kTan3PiOver8 = 2.41421356237309504880, kMoreBits = 6.123233995736765886130e-17;
    const double ax = std::abs(x);
    double offset = 0, extra = 0, t = 0;
    if (y > kTan3PiOver8 * ax) {
        offset = std::numbers::pi / 2;
        extra = kMoreBits;
        t = -ax / y;
    } else if (y <= 0.66 * ax) {
        t = y / ax;
    } else {
        offset = std::numbers::pi / 4;
        extra = 0.5 * kMoreBits;
        t = (y - ax) / (y + ax);
    }
    const double z = t * t;
    const double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z - 7.500855792314704667340e1) * z -
                      1.228866684490136173410e2) * z - 6.485021904942025371773e1;
    const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z + 4.328810604912902668951e2) * z +
                      4.853903996359136964868e2) * z + 1.945506571482613964425e2;
    const double angle = offset + (t * (z * p / q) + t + extra);
    return x < 0 ? std::numbers::pi - angle : angle;
}

/// Exact unoccluded F from a differential area at x (unit normal n) to `polygon`; 0 when x sees the
/// polygon's back or nothing of it lies above x's tangent plane.
inline double pointToElementFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& polygon) {
    if (glm::dot(polygon.normal, x - polygon.centroid) <= 0) return 0;  // behind the emitting side
    // A convex polygon clipped by a plane gains at most one corner, but a point in (or a hair off) the
    // polygon's own plane sees its corners' heights as round-off of either sign (a double-sided face's
    // twin, a curved surface's neighbour): + - + - makes two corners per edge. Room for all of them.
    std::array<glm::dvec3, 8> clipped;
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
        const double gamma = angleOf(length, glm::dot(r0, r1));
        sum += gamma * glm::dot(n, c) / length;
    }
    return std::max(0.0, sum / (2 * std::numbers::pi));
}

/// pointToElementFormFactor in float, the polygon's four (or three) edges in one SSE operation each,
/// where no corner lies below x's tangent plane (elsewhere, and without SSE, the double routine, which
/// clips): the exact kernel of the gather rows and of refinement's links near a source, whose
/// weights and form factors are floats. The angle is Cephes' atanf (S. L. Moshier: range reduction
/// by tan(pi/8), a cubic in t^2); within 5e-6 of the double routine relative to the kernel where it
/// is used, nearer than the 5 x 5 rule's distance (farther, the edges' terms cancel more: 5e-5 at
/// 1,000 A; test_hierarchical_scaling.cpp), at ~35 ns a call against ~85 ns: the double routine's
/// eight divisions and branches per polygon were ~9% of the Cornell box's hierarchical solve.
inline double pointToElementFormFactorFloat(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& polygon) {
#if defined(__SSE2__)
    if (glm::dot(polygon.normal, x - polygon.centroid) <= 0) return 0;  // behind the emitting side
    const int corners = polygon.count;
    if (corners < 3 || corners > 4) return pointToElementFormFactor(x, n, polygon);
    std::array<glm::vec3, 4> r{};
    for (int i = 0; i < corners; ++i) {
        const glm::dvec3 offset = polygon.vertices[static_cast<std::size_t>(i)] - x;
        if (glm::dot(n, offset) < 0) return pointToElementFormFactor(x, n, polygon);  // clipped: in double
        r[static_cast<std::size_t>(i)] = glm::vec3(offset);
    }
    // Lane i holds edge i, from R_i to R_{i+1}; a triangle's fourth lane is the edge R_0 to R_0,
    // whose cross product is zero and which the length mask drops. The lanes are set from
    // registers: scalar stores read back as one vector stalled store forwarding.
    const bool quad = corners == 4;
    const glm::vec3& fourth = quad ? r[3] : r[0];
    const __m128 r0x = _mm_setr_ps(r[0].x, r[1].x, r[2].x, fourth.x), r0y = _mm_setr_ps(r[0].y, r[1].y, r[2].y, fourth.y),
                 r0z = _mm_setr_ps(r[0].z, r[1].z, r[2].z, fourth.z);
    const __m128 r1x = _mm_setr_ps(r[1].x, r[2].x, fourth.x, r[0].x), r1y = _mm_setr_ps(r[1].y, r[2].y, fourth.y, r[0].y),
                 r1z = _mm_setr_ps(r[1].z, r[2].z, fourth.z, r[0].z);
    // c = R_{i+1} x R_i, as the double routine.
    const __m128 cx = _mm_sub_ps(_mm_mul_ps(r1y, r0z), _mm_mul_ps(r1z, r0y));
    const __m128 cy = _mm_sub_ps(_mm_mul_ps(r1z, r0x), _mm_mul_ps(r1x, r0z));
    const __m128 cz = _mm_sub_ps(_mm_mul_ps(r1x, r0y), _mm_mul_ps(r1y, r0x));
    const __m128 length = _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(cx, cx), _mm_mul_ps(cy, cy)), _mm_mul_ps(cz, cz)));
    const __m128 cosine = _mm_add_ps(_mm_add_ps(_mm_mul_ps(r0x, r1x), _mm_mul_ps(r0y, r1y)), _mm_mul_ps(r0z, r1z));
    // gamma = atan2(length, cosine) in [0, pi]: atan of t = min / max of |length| and |cosine| in
    // [0, 1], reduced to [-tan(pi/8), tan(pi/8)] by pi/4 - atan((1 - t) / (1 + t)).
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    const __m128 absCosine = _mm_andnot_ps(_mm_set1_ps(-0.0f), cosine);
    const __m128 high = _mm_max_ps(length, absCosine), low = _mm_min_ps(length, absCosine);
    const __m128 used = _mm_cmpgt_ps(length, zero);  // x on an edge's line: the edge subtends no angle
    const __m128 t = _mm_div_ps(low, _mm_or_ps(high, _mm_andnot_ps(used, one)));
    const __m128 reduce = _mm_cmpgt_ps(t, _mm_set1_ps(0.414213562373095f));
    const __m128 u = _mm_or_ps(_mm_and_ps(reduce, _mm_div_ps(_mm_sub_ps(t, one), _mm_add_ps(t, one))), _mm_andnot_ps(reduce, t));
    const __m128 z = _mm_mul_ps(u, u);
    __m128 poly = _mm_sub_ps(_mm_mul_ps(_mm_set1_ps(8.05374449538e-2f), z), _mm_set1_ps(1.38776856032e-1f));
    poly = _mm_add_ps(_mm_mul_ps(poly, z), _mm_set1_ps(1.99777106478e-1f));
    poly = _mm_sub_ps(_mm_mul_ps(poly, z), _mm_set1_ps(3.33329491539e-1f));
    __m128 angle = _mm_add_ps(_mm_mul_ps(_mm_mul_ps(poly, z), u), u);
    angle = _mm_add_ps(angle, _mm_and_ps(reduce, _mm_set1_ps(static_cast<float>(std::numbers::pi / 4))));
    const __m128 steep = _mm_cmpgt_ps(length, absCosine);  // the angle from the cosine's axis is pi/2 - atan(t)
    angle = _mm_or_ps(_mm_and_ps(steep, _mm_sub_ps(_mm_set1_ps(static_cast<float>(std::numbers::pi / 2)), angle)), _mm_andnot_ps(steep, angle));
    const __m128 obtuse = _mm_cmplt_ps(cosine, zero);
    angle = _mm_or_ps(_mm_and_ps(obtuse, _mm_sub_ps(_mm_set1_ps(static_cast<float>(std::numbers::pi)), angle)), _mm_andnot_ps(obtuse, angle));
    const __m128 normalDotC = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(static_cast<float>(n.x)), cx), _mm_mul_ps(_mm_set1_ps(static_cast<float>(n.y)), cy)),
                                         _mm_mul_ps(_mm_set1_ps(static_cast<float>(n.z)), cz));
    const __m128 terms = _mm_and_ps(used, _mm_div_ps(_mm_mul_ps(angle, normalDotC), _mm_or_ps(length, _mm_andnot_ps(used, one))));
    alignas(16) std::array<float, 4> lanes{};
    _mm_store_ps(lanes.data(), terms);
    const double sum = (static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]);
    return std::max(0.0, sum / (2 * std::numbers::pi));
#else
    return pointToElementFormFactor(x, n, polygon);
#endif
}

/// Squared distance over source area beyond which farFieldFormFactor stands in for the exact kernel.
/// There the source is small enough that a 2 x 2 Gauss rule of the point-to-point kernel over it is
/// within 0.2% of Lambert's exact integral for oblique pairs (tests/unit/test_hierarchical_scaling.cpp;
/// the one-point disk estimate A cos cos / (pi r^2 + A) it replaces was 1.5-2.7% low there).
inline constexpr double kFarFieldDistanceSquaredOverArea = 32;

/// Sets of rays elementVisibility draws at most while none of a set's rays weighs.
inline constexpr int kVisibilityRounds = 4;

/// F from a differential area at x (unit normal n) to a source small against its distance: the
/// point-to-point kernel cos(theta_x) cos(theta_q) / (pi r^2) integrated over the source by a 2 x 2
/// Gauss-Legendre rule on a quad (bilinear map, its Jacobian at each node) or the degree-2 Strang-Fix
/// rule on a triangle. The kernel is smooth where no corner of the source lies below x's tangent
/// plane, so the rule's error falls like (A / r^2)^2 instead of the one-point rule's A / r^2.
/// Returns a negative value when some corner of the source is below that plane: the caller must then
/// clip, i.e. use pointToElementFormFactor.
inline double farFieldFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source) {
    for (int i = 0; i < source.count; ++i)
        if (glm::dot(n, source.vertices[static_cast<std::size_t>(i)] - x) <= 0) return -1;
    if (glm::dot(source.normal, x - source.centroid) <= 0) return 0;  // behind the emitting side
    const auto kernel = [&](const glm::dvec3& y) {
        const glm::dvec3 d = y - x;
        const double r2 = glm::dot(d, d);
        return std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
    };
    const auto& v = source.vertices;
    double sum = 0;
    if (source.count == 4) {
        static constexpr std::array<double, 2> node{0.21132486540518713, 0.78867513459481287};
        double weights = 0;
        for (const double u : node)
            for (const double w : node) {
                const glm::dvec3 y = (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
                const glm::dvec3 du = (1 - w) * (v[1] - v[0]) + w * (v[2] - v[3]);
                const glm::dvec3 dw = (1 - u) * (v[3] - v[0]) + u * (v[2] - v[1]);
                const double jacobian = glm::length(glm::cross(du, dw));
                sum += jacobian * kernel(y);
                weights += jacobian;
            }
        return weights > 0 ? source.area * sum / (weights * std::numbers::pi) : 0;
    }
    for (int i = 0; i < 3; ++i) {
        const auto a = static_cast<std::size_t>(i);
        sum += kernel((4.0 * v[a] + v[(a + 1) % 3] + v[(a + 2) % 3]) / 6.0);
    }
    return source.area * sum / (3 * std::numbers::pi);
}

/// Squared distance (from the source's centroid less sqrt(A)) over source area beyond which
/// gaussFormFactor stands in for the exact kernel in the gather rows: its 3 x 3 rule was within
/// 0.006% of Lambert's integral there on 500k random oblique pairs (the 2 x 2 rule 0.45%), at
/// about half the cost of the contour integral's clipping and four atan2.
inline constexpr double kGaussDistanceSquaredOverArea = 6;

/// The same measure beyond which a 5 x 5 Gauss rule stands in for Lambert's integral in the gather
/// rows (closer than kGaussDistanceSquaredOverArea). On 40k random pairs per distance (quads and
/// triangles ~0.1 m, oblique directions, any receiver normal with the source above its horizon;
/// scratch study) the rules' worst relative error against Lambert's integral: 5 x 5 at 1 A 8.6e-5,
/// at 2 A 1.9e-5, at 6 A 1.6e-6; the 3 x 3 rule the rows already use at 6 A 8.0e-4. So the 5 x 5
/// rule from 1 A is ten times closer to the exact kernel than the rows' existing boundary, without
/// the contour integral's clipping and atan (docs/ARCHITECTURE.md, "Accuracy", Hierarchical item 20).
inline constexpr double kNearGaussDistanceSquaredOverArea = 1;

/// F from a differential area at x (unit normal n) to `source` by a 3 x 3 Gauss rule of the
/// point-to-point kernel over it (forGaussPoints' map); negative when a corner of the source is
/// below x's tangent plane (the caller must clip: pointToElementFormFactor).
inline double gaussFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source);

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

/// Calls visit(x, w) for the n x n Gauss-Legendre points of the polygon (n = 2, 3 or 5; bilinear map on
/// a quad, the collapsed Duffy map on a triangle), w the area weights, which sum to 1.
template <class Visit>
void forGaussPoints(const PatchPolygon& polygon, int n, Visit&& visit) {
    static constexpr std::array<double, 2> node2{0.21132486540518713, 0.78867513459481287};
    static constexpr std::array<double, 2> weight2{0.5, 0.5};
    static constexpr std::array<double, 3> node3{0.1127016653792583, 0.5, 0.8872983346207417};
    static constexpr std::array<double, 3> weight3{5.0 / 18, 8.0 / 18, 5.0 / 18};
    static constexpr std::array<double, 5> node5{0.04691007703066800, 0.23076534494715845, 0.5, 0.76923465505284155,
                                                 0.95308992296933200};
    static constexpr std::array<double, 5> weight5{0.11846344252809454, 0.23931433524968324, 0.28444444444444444,
                                                   0.23931433524968324, 0.11846344252809454};
    const double* node = n == 5 ? node5.data() : n == 3 ? node3.data() : node2.data();
    const double* weight = n == 5 ? weight5.data() : n == 3 ? weight3.data() : weight2.data();
    const int count = n == 5 ? 5 : n == 3 ? 3 : 2;
    const auto& v = polygon.vertices;
    std::array<glm::dvec3, 25> points;
    std::array<double, 25> weights;
    double total = 0;
    for (int i = 0; i < count; ++i)
        for (int k = 0; k < count; ++k) {
            const double u = node[i], w = node[k];
            glm::dvec3 x, du, dw;
            if (polygon.count == 4) {
                x = (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
                du = (1 - w) * (v[1] - v[0]) + w * (v[2] - v[3]);
                dw = (1 - u) * (v[3] - v[0]) + u * (v[2] - v[1]);
            } else {
                x = v[0] + u * (v[1] - v[0]) + u * w * (v[2] - v[1]);
                du = (v[1] - v[0]) + w * (v[2] - v[1]);
                dw = u * (v[2] - v[1]);
            }
            const auto j = static_cast<std::size_t>(i * count + k);
            points[j] = x;
            weights[j] = weight[i] * weight[k] * glm::length(glm::cross(du, dw));
            total += weights[j];
        }
    if (!(total > 0)) return;
    for (std::size_t j = 0; j < static_cast<std::size_t>(count * count); ++j) visit(points[j], weights[j] / total);
}

inline double gaussFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source) {
    for (int i = 0; i < source.count; ++i)
        if (glm::dot(n, source.vertices[static_cast<std::size_t>(i)] - x) <= 0) return -1;
    if (glm::dot(source.normal, x - source.centroid) <= 0) return 0;  // behind the emitting side
    double sum = 0;
    forGaussPoints(source, 3, [&](const glm::dvec3& y, double w) {
        const glm::dvec3 d = y - x;
        const double r2 = glm::dot(d, d);
        sum += w * std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
    });
    return source.area * sum / std::numbers::pi;
}

/// A source's quadrature nodes for gaussFormFactor (3 x 3) and farFieldFormFactor (2 x 2 on a quad,
/// 3 points on a triangle), with their weights normalised to sum 1: the gather rows evaluate the
/// same source's rules at thousands of points, and computing the bilinear map and its Jacobians at
/// every call was most of each call's cost.
struct SourceRule {
    std::array<glm::dvec3, 9> gauss{};
    std::array<double, 9> gaussWeight{};
    std::array<glm::dvec3, 4> far{};
    std::array<double, 4> farWeight{};
    int gaussCount = 0, farCount = 0;
    /// Squared distances from the centroid beyond which (distance - sqrt(A))^2 / A exceeds
    /// kNearGaussDistanceSquaredOverArea, kGaussDistanceSquaredOverArea and kFarFieldDistanceSquaredOverArea.
    double nearDistance2 = 0, gaussDistance2 = 0, farDistance2 = 0;
    /// The largest distance of a corner from the centroid: a point whose tangent plane lies farther
    /// below the centroid has every corner above it (ruleFormFactor's horizon test, skipped).
    double radius = 0;
    /// The same nodes in float, as offsets from the source's centroid, in blocks of four for one SSE
    /// operation each (x, y, z, weight; the blocks padded with node 0 at weight 0): ruleFormFactor's
    /// kernel. Offsets keep float's 7 digits relative to the source's size, not the scene's.
    alignas(16) std::array<float, 12> gaussX{}, gaussY{}, gaussZ{}, gaussW{};
    alignas(16) std::array<float, 4> farX{}, farY{}, farZ{}, farW{};
    /// The 5 x 5 rule's 25 nodes, the same way (ruleFormFactor with RuleOrder::Near).
    alignas(16) std::array<float, 28> nearX{}, nearY{}, nearZ{}, nearW{};
};

inline SourceRule makeSourceRule(const PatchPolygon& source) {
    SourceRule rule;
    const double edge = std::sqrt(source.area);
    rule.gaussDistance2 = std::pow(edge + std::sqrt(kGaussDistanceSquaredOverArea * source.area), 2);
    rule.farDistance2 = std::pow(edge + std::sqrt(kFarFieldDistanceSquaredOverArea * source.area), 2);
    rule.nearDistance2 = std::pow(edge + std::sqrt(kNearGaussDistanceSquaredOverArea * source.area), 2);
    for (const glm::dvec3& corner : source.corners()) rule.radius = std::max(rule.radius, glm::length(corner - source.centroid));
    forGaussPoints(source, 3, [&](const glm::dvec3& y, double w) {
        rule.gauss[static_cast<std::size_t>(rule.gaussCount)] = y;
        rule.gaussWeight[static_cast<std::size_t>(rule.gaussCount++)] = w;
    });
    const auto& v = source.vertices;
    if (source.count == 4) {
        static constexpr std::array<double, 2> node{0.21132486540518713, 0.78867513459481287};
        double weights = 0;
        for (const double u : node)
            for (const double w : node) {
                const glm::dvec3 du = (1 - w) * (v[1] - v[0]) + w * (v[2] - v[3]);
                const glm::dvec3 dw = (1 - u) * (v[3] - v[0]) + u * (v[2] - v[1]);
                const double jacobian = glm::length(glm::cross(du, dw));
                rule.far[static_cast<std::size_t>(rule.farCount)] = (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
                rule.farWeight[static_cast<std::size_t>(rule.farCount++)] = jacobian;
                weights += jacobian;
            }
        for (double& w : rule.farWeight) w = weights > 0 ? w / weights : 0;
    } else if (source.count == 3) {
        for (std::size_t a = 0; a < 3; ++a) {
            rule.far[a] = (4.0 * v[a] + v[(a + 1) % 3] + v[(a + 2) % 3]) / 6.0;
            rule.farWeight[a] = 1.0 / 3;
        }
        rule.farCount = 3;
    }
    const auto pack = [&](const auto& nodes, const auto& weights, int count, auto& x, auto& y, auto& z, auto& w) {
        for (std::size_t j = 0; j < x.size(); ++j) {
            const bool real = static_cast<int>(j) < count;
            const glm::dvec3 offset = (real ? nodes[j] : nodes[0]) - source.centroid;
            x[j] = static_cast<float>(offset.x);
            y[j] = static_cast<float>(offset.y);
            z[j] = static_cast<float>(offset.z);
            w[j] = real ? static_cast<float>(weights[j]) : 0.0f;
        }
    };
    if (rule.gaussCount > 0) pack(rule.gauss, rule.gaussWeight, rule.gaussCount, rule.gaussX, rule.gaussY, rule.gaussZ, rule.gaussW);
    if (source.count >= 3) {
        std::array<glm::dvec3, 25> nodes{};
        std::array<double, 25> weights{};
        std::size_t filled = 0;
        forGaussPoints(source, 5, [&](const glm::dvec3& y, double w) {
            nodes[filled] = y;
            weights[filled++] = w;
        });
        pack(nodes, weights, 25, rule.nearX, rule.nearY, rule.nearZ, rule.nearW);
    }
    if (rule.farCount > 0) pack(rule.far, rule.farWeight, rule.farCount, rule.farX, rule.farY, rule.farZ, rule.farW);
    return rule;
}

/// Which of a source's precomputed rules ruleFormFactor evaluates: farFieldFormFactor's 2 x 2,
/// gaussFormFactor's 3 x 3, or the 5 x 5 rule (kNearGaussDistanceSquaredOverArea).
enum class RuleOrder { Far, Gauss, Near };

/// gaussFormFactor (`far` false) or farFieldFormFactor (`far` true) by the source's precomputed nodes:
/// the same rules, negative when a corner of the source is below x's tangent plane. A corner on that
/// plane (within 1e-9 of its distance from x: round-off) does not count as below: a source touching
/// x's plane (a wall's element along the floor, seen from the floor) has no horizon to clip, its
/// kernel stays smooth (the cosine at x falls linearly to zero at the touching edge), and the rule
/// holds as well there (tests/unit/test_hierarchical_scaling.cpp, against the catalog's perpendicular
/// rectangle). Such sources were 3 in 4 of the rows' exact kernels that lay beyond the rules' distance.
inline double ruleFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source, const SourceRule& rule,
                             RuleOrder order);

inline double ruleFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source, const SourceRule& rule,
                             bool far) {
    return ruleFormFactor(x, n, source, rule, far ? RuleOrder::Far : RuleOrder::Gauss);
}

inline double ruleFormFactor(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source, const SourceRule& rule,
                             RuleOrder order) {
    const bool far = order == RuleOrder::Far, near = order == RuleOrder::Near;
    // Corners below x's tangent plane: none where the centroid stands higher above it than any corner
    // lies from the centroid, and the test per corner is skipped.
    if (!(glm::dot(n, source.centroid - x) > rule.radius))
        for (int i = 0; i < source.count; ++i) {
            const glm::dvec3 r = source.vertices[static_cast<std::size_t>(i)] - x;
            const double height = glm::dot(n, r);
            if (height < 0 && height * height > 1e-18 * glm::dot(r, r)) return -1;
        }
    if (glm::dot(source.normal, x - source.centroid) <= 0) return 0;  // behind the emitting side
#if defined(__SSE2__)
    // Four nodes per SSE operation in float (the rows' weights are floats anyway): within 1e-6 of the
    // double rule (test_hierarchical_scaling.cpp), which was most of the rows' kernel time. The
    // kernel as (n.d / r^2)(-m.d / r^2): no r^4 to leave float's range at any scale.
    const glm::dvec3 at = x - source.centroid;
    const __m128 px = _mm_set1_ps(static_cast<float>(at.x)), py = _mm_set1_ps(static_cast<float>(at.y)),
                 pz = _mm_set1_ps(static_cast<float>(at.z));
    const __m128 nx = _mm_set1_ps(static_cast<float>(n.x)), ny = _mm_set1_ps(static_cast<float>(n.y)),
                 nz = _mm_set1_ps(static_cast<float>(n.z));
    const __m128 mx = _mm_set1_ps(static_cast<float>(-source.normal.x)), my = _mm_set1_ps(static_cast<float>(-source.normal.y)),
                 mz = _mm_set1_ps(static_cast<float>(-source.normal.z));
    const float* X = far ? rule.farX.data() : near ? rule.nearX.data() : rule.gaussX.data();
    const float* Y = far ? rule.farY.data() : near ? rule.nearY.data() : rule.gaussY.data();
    const float* Z = far ? rule.farZ.data() : near ? rule.nearZ.data() : rule.gaussZ.data();
    const float* W = far ? rule.farW.data() : near ? rule.nearW.data() : rule.gaussW.data();
    const int blocks = far ? 1 : near ? 7 : 3;
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    __m128 sum = zero;
    for (int b = 0; b < blocks; ++b) {
        const __m128 dx = _mm_sub_ps(_mm_load_ps(X + 4 * b), px), dy = _mm_sub_ps(_mm_load_ps(Y + 4 * b), py),
                     dz = _mm_sub_ps(_mm_load_ps(Z + 4 * b), pz);
        const __m128 r2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
        const __m128 cosX = _mm_max_ps(zero, _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)), _mm_mul_ps(nz, dz)));
        const __m128 cosQ = _mm_max_ps(zero, _mm_add_ps(_mm_add_ps(_mm_mul_ps(mx, dx), _mm_mul_ps(my, dy)), _mm_mul_ps(mz, dz)));
        const __m128 inverse = _mm_div_ps(one, r2);
        sum = _mm_add_ps(sum, _mm_mul_ps(_mm_load_ps(W + 4 * b), _mm_mul_ps(_mm_mul_ps(cosX, inverse), _mm_mul_ps(cosQ, inverse))));
    }
    alignas(16) std::array<float, 4> lanes{};
    _mm_store_ps(lanes.data(), sum);
    const double total = (static_cast<double>(lanes[0]) + lanes[1]) + (static_cast<double>(lanes[2]) + lanes[3]);
    return source.area * total / std::numbers::pi;
#else
    if (near) {  // the float nodes (offsets from the centroid), as the SSE path reads them
        const glm::dvec3 at = x - source.centroid;
        double sum = 0;
        for (std::size_t j = 0; j < rule.nearW.size(); ++j) {
            const glm::dvec3 d = glm::dvec3(rule.nearX[j], rule.nearY[j], rule.nearZ[j]) - at;
            const double r2 = glm::dot(d, d);
            if (rule.nearW[j] > 0)
                sum += rule.nearW[j] * std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
        }
        return source.area * sum / std::numbers::pi;
    }
    const glm::dvec3* nodes = far ? rule.far.data() : rule.gauss.data();
    const double* weights = far ? rule.farWeight.data() : rule.gaussWeight.data();
    const int count = far ? rule.farCount : rule.gaussCount;
    double sum = 0;
    for (int j = 0; j < count; ++j) {
        const glm::dvec3 d = nodes[j] - x;
        const double r2 = glm::dot(d, d);
        sum += weights[j] * std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
    }
    return source.area * sum / std::numbers::pi;
#endif
}

/// The unoccluded kernel of a link receiver <- source: `mean`, F(receiver -> source); `spread`, how
/// much the point kernel varies over the receiver (the error of pushing one value down to all of it);
/// `atChildren`, the kernel's mean over each of the receiver's four children-to-be (childCentroids'
/// order), scaled so that their average is `mean`: what push-pull hands each child (ReceiverShape.h).
struct LinkKernel {
    double mean = 0, spread = 0;
    std::array<double, 4> atChildren{};
};

/// The exact kernel (exact over the source) at the centroids of the receiver's four children: their
/// mean is the link's form factor, their spread (with the centroid's value: four symmetric points
/// alone would miss a source centred over the receiver) how much the receiver's irradiance from
/// this source varies across it. Far for the source's size, farFieldFormFactor replaces Lambert's
/// contour integral (whose four atan2 per point were half of refinement's time). Close for their
/// size (e.g. sharing an edge) the 4-point mean is biased and gaussMeanKernel replaces it; near
/// contact the kernel climbs like -log of the distance to the shared edge, which interior points do
/// not see, so the receiver's corners (a tenth of the way in) join the spread: a link whose
/// receiver touches its source refines until the irradiance a corner leaf would miss is within the
/// tolerance (the furnace's worst leaves were such corners, 14-27% off before).
inline LinkKernel linkKernel(const PatchPolygon& p, const PatchPolygon& q, const SourceRule* rule = nullptr) {
    const glm::dvec3 apart = p.centroid - q.centroid;
    const double reach = std::sqrt(p.area) + std::sqrt(q.area);
    // The receiver's sample points lie within about sqrt(A_p) of its centroid.
    const double nearestSample = std::max(0.0, glm::length(apart) - std::sqrt(p.area));
    const bool far = nearestSample * nearestSample > kFarFieldDistanceSquaredOverArea * q.area;
    // With the source's precomputed rules, each point takes the rule its own distance allows (as the
    // gather rows' kernel does), Lambert's integral only nearer than kNearGaussDistanceSquaredOverArea
    // or where the source crosses the point's horizon: the contour integral at five to eighteen
    // points per link was most of refinement's time.
    const auto kernel = [&](const glm::dvec3& x) {
        if (rule != nullptr) {
            const glm::dvec3 d = q.centroid - x;
            const double distance2 = glm::dot(d, d);
            if (distance2 > rule->nearDistance2) {
                const RuleOrder order = distance2 > rule->farDistance2 ? RuleOrder::Far
                                        : distance2 > rule->gaussDistance2 ? RuleOrder::Gauss
                                                                           : RuleOrder::Near;
                const double f = ruleFormFactor(x, p.normal, q, *rule, order);
                if (f >= 0) return f;
            }
            return pointToElementFormFactorFloat(x, p.normal, q);
        }
        return pointToElementFormFactor(x, p.normal, q, far);
    };
    const double atCentroid = kernel(p.centroid);
    double sum = 0, lowest = atCentroid, highest = atCentroid;
    std::array<double, 4> atChildren{};
    const std::array<glm::dvec3, 4> children = childCentroids(p);
    for (std::size_t c = 0; c < children.size(); ++c) {
        const double f = kernel(children[c]);
        atChildren[c] = f;
        sum += f;
        lowest = std::min(lowest, f);
        highest = std::max(highest, f);
    }
    double mean = 0.25 * sum;
    if (mean > 0 && glm::dot(apart, apart) < 2.25 * reach * reach) {
        if (rule != nullptr) {
            mean = 0;
            forGaussPoints(p, 3, [&](const glm::dvec3& x, double weight) { mean += weight * kernel(x); });
        } else {
            mean = gaussMeanKernel(p, q);
        }
        for (const glm::dvec3& corner : p.corners()) {
            const double atCorner = rule != nullptr ? kernel(0.9 * corner + 0.1 * p.centroid)
                                                    : pointToElementFormFactor(0.9 * corner + 0.1 * p.centroid, p.normal, q);
            lowest = std::min(lowest, atCorner);
            highest = std::max(highest, atCorner);
        }
    }
    // The children's values keep the link's mean (the Gauss rule's where it replaced the 4-point one).
    for (double& f : atChildren) f = sum > 0 ? f * 4 * mean / sum : mean;
    return {mean, highest - lowest, atChildren};
}

/// True when some of each element lies strictly in front of the other: otherwise no light passes.
inline bool facing(const PatchPolygon& a, const PatchPolygon& b) {
    const auto someInFront = [](const PatchPolygon& of, const PatchPolygon& plane) {
        const double tolerance = planarityTolerance(of, plane);  // a double-sided face's twins never link
        for (const glm::dvec3& v : of.corners())
            if (glm::dot(plane.normal, v - plane.centroid) > tolerance) return true;
        return false;
    };
    return someInFront(a, b) && someInFront(b, a);
}

/// The shaft between two polygons a and b, their convex hull (Haines, Wallace, "Shaft culling for
/// efficient ray-cast radiosity", Eurographics Workshop on Rendering 1991, with the hull's own planes
/// instead of its boxes): its bounding box and the planes that have the whole hull on their inner
/// side, found among a's and b's planes and the planes through an edge of one polygon and a corner
/// of the other (every side of the hull is one of them).
class Shaft {
public:
    Shaft(const PatchPolygon& a, const PatchPolygon& b, double tolerance) : tolerance_(tolerance) {
        for (const glm::dvec3& v : a.corners()) hull_[hullCount_++] = v;
        for (const glm::dvec3& v : b.corners()) hull_[hullCount_++] = v;
        low_ = high_ = hull_[0];
        for (std::size_t i = 1; i < hullCount_; ++i) {
            low_ = glm::min(low_, hull_[i]);
            high_ = glm::max(high_, hull_[i]);
        }
        addPlane(a.normal, a.centroid);
        addPlane(b.normal, b.centroid);
        const auto sides = [&](const PatchPolygon& edges, const PatchPolygon& corners) {
            for (int i = 0; i < edges.count; ++i) {
                const glm::dvec3& p0 = edges.vertices[static_cast<std::size_t>(i)];
                const glm::dvec3 edge = edges.vertices[static_cast<std::size_t>((i + 1) % edges.count)] - p0;
                for (const glm::dvec3& v : corners.corners()) addPlane(glm::cross(edge, v - p0), p0);
            }
        };
        sides(a, b);
        sides(b, a);
    }

    /// True when a plane separates the shaft from the convex polygon with corners `t`, so no segment
    /// from a point of a to a point of b meets it: the boxes' axes, t's own plane, or one of the
    /// hull's planes. False when none does, which is always safe: the caller then casts rays.
    /// Touching within the tolerance (m) counts as separated: segments grazing t's edge or plane are
    /// a measure-zero set of the pair's segments.
    [[nodiscard]] bool separates(std::span<const glm::dvec3> t) const {
        glm::dvec3 low = t[0], high = t[0];
        for (const glm::dvec3& v : t) {
            low = glm::min(low, v);
            high = glm::max(high, v);
        }
        for (int axis = 0; axis < 3; ++axis)
            if (low[axis] > high_[axis] + tolerance_ || high[axis] < low_[axis] - tolerance_) return true;
        for (std::size_t k = 0; k < planeCount_; ++k) {
            double farthest = -std::numeric_limits<double>::infinity();
            for (const glm::dvec3& v : t) farthest = std::max(farthest, glm::dot(normals_[k], v) - offsets_[k]);
            if (farthest <= tolerance_) return true;
        }
        // t's own plane (Newell's normal: any convex polygon, any winding), with t's corners on it.
        glm::dvec3 n(0.0);
        for (std::size_t i = 0; i < t.size(); ++i) n += glm::cross(t[i], t[(i + 1) % t.size()]);
        const double length = glm::length(n);
        if (!(length > 0)) return false;
        n /= length;
        double tLow = std::numeric_limits<double>::infinity(), tHigh = -tLow;
        for (const glm::dvec3& v : t) {
            tLow = std::min(tLow, glm::dot(n, v - t[0]));
            tHigh = std::max(tHigh, glm::dot(n, v - t[0]));
        }
        double hullLow = std::numeric_limits<double>::infinity(), hullHigh = -hullLow;
        for (std::size_t i = 0; i < hullCount_; ++i) {
            hullLow = std::min(hullLow, glm::dot(n, hull_[i] - t[0]));
            hullHigh = std::max(hullHigh, glm::dot(n, hull_[i] - t[0]));
        }
        return (hullLow >= -tolerance_ && tHigh <= tolerance_) || (hullHigh <= tolerance_ && tLow >= -tolerance_);
    }

private:
    /// Keeps the plane through `origin` with normal +-n when the whole hull lies on one side of it
    /// (within the tolerance), oriented so that the hull is on its positive side.
    void addPlane(const glm::dvec3& n, const glm::dvec3& origin) {
        const double length = glm::length(n);
        if (!(length > 0)) return;
        const glm::dvec3 unit = n / length;
        double hullLow = std::numeric_limits<double>::infinity(), hullHigh = -hullLow;
        for (std::size_t i = 0; i < hullCount_; ++i) {
            const double d = glm::dot(unit, hull_[i] - origin);
            hullLow = std::min(hullLow, d);
            hullHigh = std::max(hullHigh, d);
        }
        if (hullLow >= -tolerance_) {
            normals_[planeCount_] = unit;
            offsets_[planeCount_++] = glm::dot(unit, origin);
        } else if (hullHigh <= tolerance_) {
            normals_[planeCount_] = -unit;
            offsets_[planeCount_++] = -glm::dot(unit, origin);
        }
    }

    double tolerance_;
    std::array<glm::dvec3, 8> hull_{};
    std::size_t hullCount_ = 0;
    glm::dvec3 low_{0.0}, high_{0.0};
    // Inner side: dot(normal, x) - offset >= 0. At most a's, b's and 2 x 4 x 4 sides.
    std::array<glm::dvec3, 34> normals_{};
    std::array<double, 34> offsets_{};
    std::size_t planeCount_ = 0;
};

/// SplitMix64: a deterministic, well-mixed hash for the stratified jitter.
inline std::uint64_t mix(std::uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
inline double unitInterval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

/// Strata per dimension in one set of rays; larger sets are cast as several sets.
inline constexpr int kMaxStrataPerSet = 256;

/// A point of an element for (u, v) in the unit square: bilinear on a quad, the square-root warp on a
/// triangle (both area-uniform for the elements' parallelogram-like quads and all triangles), with the
/// map's terms worked out once for the many points of a set of rays: c0 + u (c1 - c0) + v (c3 - c0) +
/// uv (c0 - c1 + c2 - c3) on a quad, c0 + s (c1 - c0) + s v (c2 - c1) with s = sqrt(u) on a triangle.
class ElementPoints {
public:
    explicit ElementPoints(const PatchPolygon& p) : quad_(p.count == 4), origin_(p.vertices[0]) {
        const auto& c = p.vertices;
        du_ = c[1] - c[0];
        dv_ = quad_ ? c[3] - c[0] : c[2] - c[1];
        duv_ = quad_ ? c[0] - c[1] + c[2] - c[3] : glm::dvec3(0.0);
    }
    [[nodiscard]] glm::dvec3 at(double u, double v) const {
        if (quad_) return origin_ + u * du_ + v * dv_ + (u * v) * duv_;
        const double s = std::sqrt(u);
        return origin_ + s * du_ + (s * v) * dv_;
    }

private:
    bool quad_;
    glm::dvec3 origin_, du_{0.0}, dv_{0.0}, duv_{0.0};
};

/// One point of p by ElementPoints' map.
inline glm::dvec3 pointOn(const PatchPolygon& p, double u, double v) { return ElementPoints(p).at(u, v); }

/// A random permutation of 0 .. n-1 (n <= kMaxStrataPerSet) by Fisher-Yates, each index drawn from a
/// 32-bit word of a hash of `seed` by multiply-shift, the product's low half left for the next draws
/// while at least 16 bits of it remain (D. Lemire, "Fast random integer generation in an interval",
/// ACM TOMACS 2019), instead of a hash per swap: the rows cast ~300k sets of a few rays, and their
/// sampling cost about as much as Embree's traversal of the rays.
inline void shuffledStrata(std::uint8_t* order, int n, std::uint64_t seed) {
    for (int k = 0; k < n; ++k) order[k] = static_cast<std::uint8_t>(k);
    std::uint64_t bits = mix(seed);
    std::uint64_t word = bits & 0xffffffffu, used = 1;
    bool spareHalf = true;  // bits' upper half not yet used
    for (int k = n - 1; k > 0; --k) {
        const auto bound = static_cast<std::uint64_t>(k + 1);
        if (used * bound > (std::uint64_t{1} << 16)) {
            if (!spareHalf) {
                seed += 0x9E3779B97F4A7C15ull;
                bits = mix(seed);
            }
            word = spareHalf ? bits >> 32 : bits & 0xffffffffu;
            spareHalf = !spareHalf;
            used = 1;
        }
        used *= bound;
        const std::uint64_t product = word * bound;
        word = product & 0xffffffffu;
        std::swap(order[k], order[static_cast<std::size_t>(product >> 32)]);
    }
}

/// One set of `rays` (at most kMaxStrataPerSet) stratified rays (see elementVisibility), added to
/// `seen` and `total` (kernel weights) and `through` (rays that got through).
inline void castVisibilitySet(double& seen, double& total, int& through, const PatchPolygon& a, const PatchPolygon& b,
                              const RayCaster& caster, int rays, std::uint64_t seed) {
    // Ray k takes stratum k of a's u and strata shuffled per set for a's v and b's u and v. Fixed
    // strides instead ((3k + 1) mod n on a, k + 1 and (3k + 2) mod n on b) made b's point a's point
    // plus one offset for every ray of the set: parallel rays, which see a penumbra as a point of the
    // source does (a Cornell box floor patch that sees 4.8% of the lamp read 0 with 64 rays).
    std::array<std::array<std::uint8_t, kMaxStrataPerSet>, 3> strata;
    for (std::size_t d = 0; d < 3; ++d) shuffledStrata(strata[d].data(), rays, seed ^ (0x6a09e667ull * (d + 1)));
    const ElementPoints onA(a), onB(b);
    constexpr double kInset = 1e-4;  // of the element's parameter range
    const double width = (1 - 2 * kInset) / rays;
    // A ray's four jitters are the four 16-bit quarters of one hash: 1/65536 of a stratum is finer
    // than anything the rays resolve.
    const auto stratum = [&](int i, std::uint64_t bits) {
        return kInset + width * (i + static_cast<double>(bits & 0xffffu) * 0x1.0p-16);
    };
    // The set's rays go to the caster together, in packets (RayCaster::occluded over spans).
    constexpr int kBatch = 16;
    std::array<glm::dvec3, kBatch> from, to;
    std::array<double, kBatch> weights;
    std::array<bool, kBatch> blocked;
    for (int first = 0; first < rays; first += kBatch) {
        const int count = std::min(kBatch, rays - first);
        for (int i = 0; i < count; ++i) {
            const int k = first + i;
            const auto j = static_cast<std::size_t>(i);
            const auto at = static_cast<std::size_t>(k);
            const std::uint64_t h = mix(seed + static_cast<std::uint64_t>(k) * 0xD1B54A32D192ED03ull);
            from[j] = onA.at(stratum(k, h), stratum(strata[0][at], h >> 16));
            to[j] = onB.at(stratum(strata[1][at], h >> 32), stratum(strata[2][at], h >> 48));
            // Each ray weighted by the point-to-point kernel: the share of the form factor, not of the
            // area pairs (they differ where a blocker sits close to one element, at a block's foot).
            const glm::dvec3 d = to[j] - from[j];
            const double r2 = glm::dot(d, d);
            weights[j] = r2 > 0 ? std::max(0.0, glm::dot(a.normal, d)) * std::max(0.0, -glm::dot(b.normal, d)) / (r2 * r2) : 0;
        }
        const auto size = static_cast<std::size_t>(count);
        caster.occluded(std::span<const glm::dvec3>(from.data(), size), std::span<const glm::dvec3>(to.data(), size),
                        std::span<bool>(blocked.data(), size));
        for (std::size_t j = 0; j < size; ++j) {
            total += weights[j];
            if (!blocked[j]) {
                seen += weights[j];
                ++through;
            }
        }
    }
}

/// `rays` stratified rays (see elementVisibility): the weighted share, -1 when none of them weighs;
/// `unblocked`, the plain fraction of rays that got through.
inline double elementVisibilityOnce(double& unblocked, const PatchPolygon& a, const PatchPolygon& b, const RayCaster& caster, int rays,
                                    std::uint64_t seed) {
    double seen = 0, total = 0;
    int through = 0;
    for (int first = 0; first < rays; first += kMaxStrataPerSet)
        castVisibilitySet(seen, total, through, a, b, caster, std::min(kMaxStrataPerSet, rays - first),
                          first == 0 ? seed : mix(seed ^ static_cast<std::uint64_t>(first)));
    unblocked = static_cast<double>(through) / rays;
    return total > 0 ? seen / total : -1.0;
}

/// The visible share of the pair's form factor from `rays` segments between the two elements, each
/// weighted by the point-to-point kernel (a ratio estimator; with every weight equal it is the unbiased
/// fraction of unblocked area pairs, and for a blocker symmetric about the pair both agree in the
/// mean, which tests/unit/test_hierarchical_accuracy.cpp checks). The rays' four coordinates (u, v
/// on each element) form a jittered Latin hypercube with strata paired by permutations shuffled per
/// set (M. McKay, R. Beckman, W. Conover, "A comparison of three methods for selecting values of
/// input variables", Technometrics 1979), so every sample is uniform over its element and the rays
/// cross the pair in as many directions as there are rays. Samples stay a hair inside each element,
/// so no ray starts on a shared edge.
inline double elementVisibility(const PatchPolygon& a, const PatchPolygon& b, const RayCaster& caster, int rays,
                                std::uint64_t seed, std::size_t* raysCast = nullptr) {
    if (rays <= 0) return 1;
    // Only rays joining parts in front of each other weigh: where every one of a set fell behind a
    // horizon (a source straddling a curved object's face's tangent plane), another set is drawn, a few
    // times over. Counting such rays' hits instead called the link hidden, for they cross the
    // receiver's own object: a tessellated sphere lost the walls straddling its faces' horizons.
    double unblocked = 1;
    for (int round = 0; round < kVisibilityRounds; ++round) {
        const double share = elementVisibilityOnce(unblocked, a, b, caster, rays, round == 0 ? seed : mix(seed + static_cast<std::uint64_t>(round)));
        if (raysCast) *raysCast += static_cast<std::size_t>(rays);
        if (share >= 0) return share;
    }
    // No ray found the parts that face each other (a sliver at a contact edge): the plain fraction
    // of rays that got through, as before the rounds (1 here put the Cornell box's blocks 2.7% over
    // Gauss-Seidel).
    return unblocked;
}

/// The visible share of F(dx -> source) from the point x (unit normal n): k x k jittered strata
/// over the source, each ray weighted by the point-to-point kernel so that the share times the
/// unoccluded F estimates the occluded integral (Wallace, Elmquist, Haines 1989's gather at a point).
inline double pointVisibility(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& source,
                              const RayCaster& caster, int raysPerSide, std::uint64_t seed) {
    if (raysPerSide <= 0) return 1;
    double seen = 0, total = 0;
    const double k = raysPerSide;
    const ElementPoints onSource(source);
    for (int i = 0; i < raysPerSide; ++i)
        for (int j = 0; j < raysPerSide; ++j) {
            const std::uint64_t h = mix(seed + static_cast<std::uint64_t>(i * raysPerSide + j));
            const double u = (i + unitInterval(h)) / k, v = (j + unitInterval(mix(h))) / k;
            const glm::dvec3 y = onSource.at(1e-4 + (1 - 2e-4) * u, 1e-4 + (1 - 2e-4) * v);
            const glm::dvec3 d = y - x;
            const double r2 = glm::dot(d, d);
            const double weight = std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
            if (weight <= 0) continue;
            total += weight;
            if (!caster.occluded(x, y)) seen += weight;
        }
    return total > 0 ? seen / total : 0;
}

} // namespace radiant::hierarchical
