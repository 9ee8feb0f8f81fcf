// Visibility between two patches as the unblocked fraction of segments joining sample points on
// them, the usual ray-cast estimate of radiosity solvers (Wallace, Elmquist & Haines, "A ray tracing
// algorithm for progressive radiosity", SIGGRAPH 1989).
//
// The sample pairs form a jittered Latin hypercube in the four dimensions (u, v on each patch):
// every dimension is stratified into visibilityRays strata whatever that number is, and linear
// congruential permutations pair the strata without storing anything. The pairs are a
// deterministic function of the seed and of the unordered pair of patches, and the segments are
// always cast in the same direction, so visibilityFraction(a, b) == visibilityFraction(b, a) and
// reciprocity A_i F_ij = A_j F_ji survives visibility exactly.
//
// The points are drawn on the part of each patch in front of the other's plane, the only parts that
// exchange light. A segment from a part behind crosses the patch's own object, or leaves a closed
// one through the patch itself, which no ray from the patch's plane can hit: a closed double-sided
// sphere's inside saw 60-90% of the walls behind its facets' backs, through those facets.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include <glm/geometric.hpp>

#include "radiometry/common/Mix64.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"

namespace radiant {
namespace {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() { return mix64(state_ += 0x9e3779b97f4a7c15ULL); }
    /// Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    std::uint64_t state_;
};

std::uint64_t polygonKey(const PatchPolygon& polygon) {
    std::uint64_t h = mix64(std::bit_cast<std::uint64_t>(polygon.centroid.x));
    h = mix64(h ^ std::bit_cast<std::uint64_t>(polygon.centroid.y));
    h = mix64(h ^ std::bit_cast<std::uint64_t>(polygon.centroid.z));
    return mix64(h ^ std::bit_cast<std::uint64_t>(polygon.area));
}

/// A permutation i -> (stride i + offset) mod n of 0..n-1, random for the generator.
class StratumPermutation {
public:
    StratumPermutation(std::uint64_t n, SplitMix64& random) : n_(n), offset_(random.next() % n) {
        stride_ = 1 + random.next() % n;
        while (std::gcd(stride_, n_) != 1) ++stride_;
    }
    [[nodiscard]] std::uint64_t operator()(std::uint64_t i) const { return (stride_ % n_ * i + offset_) % n_; }

private:
    std::uint64_t n_, offset_, stride_ = 1;
};

/// The part of a patch in front of a plane: a convex polygon of up to five corners (a quad cut by a
/// plane gains one), with the areas of its fan of triangles about corner 0.
struct FrontPart {
    std::array<glm::dvec3, 5> corners{};
    std::array<double, 3> fanArea{};
    std::size_t count = 0;
    double area = 0;
};

/// Corners within `tolerance` of the plane lie on it and are kept, so a patch touching the plane
/// along an edge (a neighbour across a crease) is not cut.
FrontPart frontPart(const PatchPolygon& polygon, const PatchPolygon& plane, double tolerance) {
    FrontPart part;
    std::array<double, 4> height{};
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const double h = glm::dot(plane.normal, polygon.vertices[i] - plane.centroid);
        height[i] = std::abs(h) <= tolerance ? 0.0 : h;
    }
    for (std::size_t i = 0; i < polygon.count; ++i) {
        const std::size_t next = (i + 1) % polygon.count;
        if (height[i] >= 0 && part.count < part.corners.size()) part.corners[part.count++] = polygon.vertices[i];
        if (((height[i] > 0 && height[next] < 0) || (height[i] < 0 && height[next] > 0)) && part.count < part.corners.size())
            part.corners[part.count++] = polygon.vertices[i] + (polygon.vertices[next] - polygon.vertices[i]) *
                                                                  (height[i] / (height[i] - height[next]));
    }
    for (std::size_t k = 1; k + 1 < part.count; ++k) {
        part.fanArea[k - 1] = 0.5 * glm::length(glm::cross(part.corners[k] - part.corners[0], part.corners[k + 1] - part.corners[0]));
        part.area += part.fanArea[k - 1];
    }
    return part;
}

/// Area-uniform point on the part from (u, v) in [0, 1)^2: the triangle of its fan is chosen by u in
/// proportion to their areas, so strata in u stay strata.
glm::dvec3 samplePart(const FrontPart& part, double u, double v) {
    std::size_t k = 0;
    const std::size_t triangles = part.count - 2;
    for (; k + 1 < triangles; ++k) {
        const double share = part.fanArea[k] / part.area;
        if (u < share) break;
        u -= share;
    }
    u = std::clamp(u / (part.fanArea[k] / part.area), 0.0, 1.0);
    const glm::dvec3& a = part.corners[0];
    const glm::dvec3& b = part.corners[k + 1];
    const glm::dvec3& c = part.corners[k + 2];
    const double root = std::sqrt(u);
    return a * (1 - root) + b * (root * (1 - v)) + c * (root * v);
}

} // namespace

double visibilityFraction(const PatchPolygon& from, const PatchPolygon& to, const RayCaster* rays,
                          const FormFactorOptions& options) {
    if (rays == nullptr || options.visibilityRays <= 0) return 1.0;
    const std::uint64_t fromKey = polygonKey(from);
    const std::uint64_t toKey = polygonKey(to);
    const bool swap = toKey < fromKey;
    const PatchPolygon& first = swap ? to : from;
    const PatchPolygon& second = swap ? from : to;
    const double tolerance = planarityTolerance(first, second);
    const FrontPart firstPart = frontPart(first, second, tolerance);
    const FrontPart secondPart = frontPart(second, first, tolerance);
    // Not facing each other: no segment carries light, and none can be blocked.
    if (firstPart.count < 3 || secondPart.count < 3 || !(firstPart.area > 0) || !(secondPart.area > 0)) return 1.0;
    SplitMix64 random(mix64(options.seed) ^ mix64(std::min(fromKey, toKey) + 3 * std::max(fromKey, toKey)));

    const auto n = static_cast<std::uint64_t>(options.visibilityRays);
    const StratumPermutation firstV(n, random), secondU(n, random), secondV(n, random);
    const double strata = static_cast<double>(n);
    std::uint64_t unblocked = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
        const glm::dvec3 p = samplePart(firstPart, (static_cast<double>(i) + random.uniform()) / strata,
                                        (static_cast<double>(firstV(i)) + random.uniform()) / strata);
        const glm::dvec3 q = samplePart(secondPart, (static_cast<double>(secondU(i)) + random.uniform()) / strata,
                                        (static_cast<double>(secondV(i)) + random.uniform()) / strata);
        if (!rays->occluded(p, q)) ++unblocked;
    }
    return static_cast<double>(unblocked) / strata;
}

} // namespace radiant
