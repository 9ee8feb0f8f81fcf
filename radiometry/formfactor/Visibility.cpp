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
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include <glm/geometric.hpp>

#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"

namespace radiant {
namespace {

std::uint64_t mix64(std::uint64_t z) {
    // SplitMix64's finaliser (Steele, Lea & Flood, OOPSLA 2014).
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

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

/// Area-uniform point on a triangle or convex quad from (u, v) in [0, 1)^2: a quad is split into
/// two triangles chosen by u in proportion to their areas, so strata in u stay strata.
glm::dvec3 samplePolygon(const PatchPolygon& polygon, double u, double v) {
    const glm::dvec3& a = polygon.vertices[0];
    glm::dvec3 b = polygon.vertices[1];
    glm::dvec3 c = polygon.vertices[2];
    if (polygon.count == 4) {
        const double firstArea = 0.5 * glm::length(glm::cross(b - a, c - a));
        const double share = polygon.area > 0 ? std::min(1.0, firstArea / polygon.area) : 0.5;
        if (u < share) {
            u /= share;
        } else {
            u = (u - share) / (1 - share);
            b = polygon.vertices[2];
            c = polygon.vertices[3];
        }
    }
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
    SplitMix64 random(mix64(options.seed) ^ mix64(std::min(fromKey, toKey) + 3 * std::max(fromKey, toKey)));

    const auto n = static_cast<std::uint64_t>(options.visibilityRays);
    const StratumPermutation firstV(n, random), secondU(n, random), secondV(n, random);
    const double strata = static_cast<double>(n);
    std::uint64_t unblocked = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
        const glm::dvec3 p = samplePolygon(first, (static_cast<double>(i) + random.uniform()) / strata,
                                           (static_cast<double>(firstV(i)) + random.uniform()) / strata);
        const glm::dvec3 q = samplePolygon(second, (static_cast<double>(secondU(i)) + random.uniform()) / strata,
                                           (static_cast<double>(secondV(i)) + random.uniform()) / strata);
        if (!rays->occluded(p, q)) ++unblocked;
    }
    return static_cast<double>(unblocked) / strata;
}

} // namespace radiant
