// The form factors of one progressive shot, from the shooter (a patch, or a block of patches of
// one face: ProgressiveShooters.h) to every receiver patch, F_{j -> shooter}. Cheapest first:
//  - a plane test culls pairs that cannot see each other, and the shooter's own face, before any
//    kernel or ray;
//  - the exact point-to-polygon (Lambert) kernel to the whole shooter at the receiver's centroid
//    when the receiver is small for its distance to the shooter's outline - the route of Wallace,
//    Elmquist, Haines, "A ray tracing algorithm for progressive radiosity", SIGGRAPH 1989 - and
//    averaged over 2 x 2 or 4 x 4 Gauss points of the receiver when it is close;
//  - visibility from rays between stratified points of the receiver and stratified sample points
//    of the shooter, drawn afresh for each shot where the group's unshot power is (a block of
//    floor half under a box shoots from its lit half only): a strong shot casts 16 + 64 rays a
//    receiver, so a shadow's edge comes out as the same area-to-area fraction Gauss-Seidel's
//    matrix holds, not as {0, 1/2, 1} from 2-4 rays (the light source shoots once, so its few-ray
//    noise never averages out); weak shots cast 2-16, and the many of them average.
//  - for a group, the kernel weighs each member by its share of the shot's power in each band, and
//    each visibility ray by what its member sends to the receiver: the light leaves from where it
//    is and in the colour it has there (a block of floor half in the lamp's light, half in the red
//    wall's, sends its red from one half), and a receiver beside the group does not count rays to
//    members beyond its horizon as shadowed; where a receiver's rays to a group disagree, its
//    visibility is resolved per member and per band (perMemberVisibility).
// F_{j->s} comes out directly, so no reciprocity division by a small receiver's area.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/common/Mix64.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/GroupedSolver.h"
#include "radiometry/solver/ParallelFor.h"
#include "radiometry/solver/ProgressiveSolver.h"

namespace radiant {

namespace {

/// Gauss-Legendre nodes and weights on [0, 1] for orders 1, 2 and 4.
struct ReceiverRule {
    int order;
    std::array<double, 4> node, weight;
};
constexpr ReceiverRule kCentroid{1, {0.5}, {1.0}};
constexpr ReceiverRule kGauss2{2, {0.2113248654051871, 0.7886751345948129}, {0.5, 0.5}};
constexpr ReceiverRule kGauss4{4,
                               {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263},
                               {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269}};

/// Receivers farther than this many of their own diameters from the shooter's outline take the
/// centroid alone (the point kernel's error from the receiver's extent falls like
/// (diameter / distance)^2); closer than kNearInDiameters, 4 x 4 points; between, 2 x 2.
constexpr double kFarInDiameters = 4.0;
constexpr double kNearInDiameters = 1.5;

/// Visibility rays per receiver, in FormFactorOptions::visibilityRays (16 by default): every
/// receiver first casts a few (2 to 16), and in a shot carrying at least kFullPenumbraShare of the
/// emitted power (the light source's) then kPenumbraRayFactor times visibilityRays (64) more,
/// against as many stratified target points per shot (until 2026-12-03 only where its first 16
/// disagreed, which was biased: shotVisibility); a shot carrying less casts fewer: the error a
/// shot leaves grows with its power, and the many weak shots' noise averages out over receivers
/// lit by all of them. Without that, 64 rays at every penumbra of every block shot made the Cornell
/// box at 10k patches 5.6x slower to residual 1e-2 (1.6 -> 9.0 s). At 0.25 the default 7 x 7 blocks
/// (2,170 patches, 62 shooters) shoot too few times for that noise to average: the blocks' gap was
/// 6.0% off converged Gauss-Seidel per patch (41% worst) on the short block's side facing the tall
/// one and 1.5% at the accuracy bench's point there; at 0.02, 1.4% / 9.5% and 0.12%, the solve
/// 0.85 -> 1.07 s (tests/unit/test_progressive_gap.cpp).
constexpr int kPenumbraRayFactor = 4;
constexpr double kFullPenumbraShare = 0.02;
/// A shot carrying at least kLightShotShare of the emitted power (a light source's) spreads
/// kLightShotTargetFactor times visibilityRays targets (256) over its shooter, and its receivers cast
/// as many penumbra rays. Every receiver of a shot sees the light through the same targets, so a
/// penumbra is read against that many points of the lamp for the whole solve (the light shoots
/// once): with 64, a floor patch in the short block's penumbra read 25 / 9 / 18% under Gauss-Seidel
/// at seeds 1-3, with 256 2 / 12 / 9%. Cornell box, seeds 1-3 against Gauss-Seidel with 64 rays: the patches'
/// mean distance 0.91 / 0.91 / 1.00% -> 0.86 / 0.77 / 0.77%, patches over 5% off 84 / 84 / 106 ->
/// 71 / 52 / 59, CPU +1-6% (docs/ARCHITECTURE.md, "Accuracy").
constexpr double kLightShotShare = 0.2;
constexpr int kLightShotTargetFactor = 16;

/// A member weighs the receiver's kernel by its centroid's point kernel (in the ratio of
/// unoccludedFromShot) once the receiver's centroid is this many of the member's areas away,
/// squared; nearer, by the exact kernel. The point kernel's error, about A / r^2, cancels in the
/// ratio but for its variation across the group.
constexpr double kRatioDistanceSquaredOverArea = 8;

/// Uniform in [0, 1) from the next state of a SplitMix64 sequence.
double nextUniform(std::uint64_t& state) {
    return static_cast<double>(mix64(state += 0x9e3779b97f4a7c15ULL) >> 11) * 0x1.0p-53;
}

/// A stride in [1, n] coprime to n, from `hash`: stepping i -> stride i mod n visits 0..n-1 once
/// each, in an order that pairs two sets of n strata without lining them up.
std::uint64_t coprimeStride(std::uint64_t hash, std::uint64_t n) {
    std::uint64_t stride = 1 + hash % n;
    while (std::gcd(stride, n) != 1) ++stride;
    return stride;
}

/// A point of the polygon from (u, v) in [0, 1)^2: bilinear on a quad (area-uniform on the
/// parallelograms meshing makes of rectangles), the square-root map on a triangle.
glm::dvec3 pointOn(const PatchPolygon& p, double u, double v) {
    const auto& c = p.vertices;
    if (p.count == 4) return (c[0] * (1 - u) + c[1] * u) * (1 - v) + (c[3] * (1 - u) + c[2] * u) * v;
    const double root = std::sqrt(u);
    return c[0] * (1 - root) + c[1] * (root * (1 - v)) + c[2] * (root * v);
}

/// Distance from x to the planar convex polygon (m).
double distanceToPolygon(const PatchPolygon& p, const glm::dvec3& x) {
    const double height = glm::dot(x - p.centroid, p.normal);
    const glm::dvec3 projected = x - height * p.normal;
    double outside = 0;  // squared in-plane distance to the nearest edge, when outside any edge
    bool inside = true;
    double nearest = 1e300;
    for (std::size_t k = 0; k < p.count; ++k) {
        const glm::dvec3& a = p.vertices[k];
        const glm::dvec3& b = p.vertices[(k + 1) % p.count];
        const glm::dvec3 edge = b - a;
        if (glm::dot(glm::cross(edge, projected - a), p.normal) < 0) inside = false;
        const double t = std::clamp(glm::dot(projected - a, edge) / glm::dot(edge, edge), 0.0, 1.0);
        const glm::dvec3 offEdge = projected - (a + t * edge);
        nearest = std::min(nearest, glm::dot(offEdge, offEdge));
    }
    if (!inside) outside = nearest;
    return std::sqrt(height * height + outside);
}

struct ShotGeometry {
    std::vector<PatchPolygon> polygons;  ///< receivers
    std::vector<Patch> patches;
    std::vector<PatchPolygon> shooters;
    std::vector<std::uint32_t> shooterSurface, shooterFace;
    std::vector<double> shooterRadius;  ///< farthest corner from the shooter's centroid, m
    std::vector<double> patchRadius;    ///< the same for each patch
    ProgressiveShooters groups;
    std::shared_ptr<const RayCaster> rays;  ///< the caller's (SolverOptions::rays) or our own
    FormFactorOptions options;
};

/// (1/A_r) integral over the receiver of F(dA_r -> shooter) dA_r: the exact Lambert kernel to the
/// whole shooter at Gauss points of the receiver's bilinear map (a triangle is a quad with its last
/// corner doubled). Unoccluded.
double receiverAverage(const PatchPolygon& receiver, const PatchPolygon& shooter, const ReceiverRule& rule) {
    if (rule.order == 1) return pointToPolygonFormFactor(receiver.centroid, receiver.normal, shooter.corners());
    const glm::dvec3 a = receiver.vertices[0], b = receiver.vertices[1], c = receiver.vertices[2];
    const glm::dvec3 d = receiver.count == 4 ? receiver.vertices[3] : c;
    double sum = 0;
    for (int i = 0; i < rule.order; ++i) {
        const double u = rule.node[static_cast<std::size_t>(i)];
        const glm::dvec3 bottom = a + (b - a) * u;
        const glm::dvec3 alongV = d + (c - d) * u - bottom;
        for (int j = 0; j < rule.order; ++j) {
            const double v = rule.node[static_cast<std::size_t>(j)];
            const glm::dvec3 alongU = (b - a) + ((c - d) - (b - a)) * v;
            const double jacobian = glm::dot(receiver.normal, glm::cross(alongU, alongV));
            sum += rule.weight[static_cast<std::size_t>(i)] * rule.weight[static_cast<std::size_t>(j)] * jacobian *
                   pointToPolygonFormFactor(bottom + alongV * v, receiver.normal, shooter.corners());
        }
    }
    return sum / receiver.area;
}

/// A shot's visibility targets and, for each, which of the group's members (index in the group) it lies on.
struct ShotTargets {
    std::vector<glm::dvec3> points;
    std::vector<std::uint32_t> member;
    /// Each target's member's normal, for a group that is not planar (patch groups); empty: the
    /// shooter's one normal.
    std::vector<glm::dvec3> normal;
    std::uint32_t shot = 0;  ///< the group's shot number (GroupShotFormFactors)
};

/// visibilityRays x kPenumbraRayFactor points (kLightShotTargetFactor for a light's shot) of the group, stratified over its members' share of the shot's power
/// (by area when no share is given): stratum t falls in the member whose cumulative share covers
/// it, at a u within that member proportional to where in its share it fell and a v from a
/// permuted stratum, so a lone patch gets a jittered Latin hypercube.
ShotTargets shotTargets(const ShotGeometry& g, std::size_t group, std::uint32_t shot, std::span<const double> memberPower,
                        double powerShare) {
    const auto members = g.groups.group(group);
    std::vector<double> cumulative(members.size());
    double total = 0;
    const bool byPower = memberPower.size() == members.size() &&
                         std::any_of(memberPower.begin(), memberPower.end(), [](double w) { return w > 0; });
    for (std::size_t k = 0; k < members.size(); ++k) {
        total += byPower ? std::max(0.0, memberPower[k]) : g.polygons[members[k]].area;
        cumulative[k] = total;
    }
    const int factor = std::abs(powerShare) >= kLightShotShare ? kLightShotTargetFactor : kPenumbraRayFactor;
    const int n = std::max(1, g.options.visibilityRays * factor);
    const auto count = static_cast<std::uint64_t>(n);
    std::uint64_t state = pairSeed(g.options.seed, group, shot);
    const std::uint64_t stride = coprimeStride(mix64(state), count);
    const std::uint64_t offset = mix64(state + 1) % count;
    ShotTargets targets;
    targets.shot = shot;
    targets.points.reserve(count);
    targets.member.reserve(count);
    for (std::uint64_t t = 0; t < count; ++t) {
        const double at = (static_cast<double>(t) + nextUniform(state)) / static_cast<double>(n) * total;
        const std::size_t k = std::min<std::size_t>(
            members.size() - 1, static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), at) -
                                                         cumulative.begin()));
        const double below = k == 0 ? 0.0 : cumulative[k - 1];
        const double share = cumulative[k] - below;
        const double u = share > 0 ? std::clamp((at - below) / share, 0.0, 1.0) : 0.5;
        const double v = (static_cast<double>((stride * t + offset) % count) + nextUniform(state)) / static_cast<double>(n);
        targets.points.push_back(pointOn(g.polygons[members[k]], u, v));
        targets.member.push_back(static_cast<std::uint32_t>(k));
    }
    return targets;
}

/// n points of the polygon stratified in u and in v (a jittered Latin hypercube, v strata permuted
/// by a stride coprime to n), drawn one at a time in index order without allocating.
class StratifiedOrigins {
public:
    StratifiedOrigins(const PatchPolygon& polygon, int n, std::uint64_t seed)
        : polygon_(polygon), count_(static_cast<std::uint64_t>(n)), state_(seed), offset_(mix64(seed + 1) % count_),
          stride_(coprimeStride(mix64(seed), count_)) {}
    glm::dvec3 next() {
        const double n = static_cast<double>(count_);
        const double u = (static_cast<double>(index_) + nextUniform(state_)) / n;
        const double v = (static_cast<double>((stride_ * index_ + offset_) % count_) + nextUniform(state_)) / n;
        ++index_;
        return pointOn(polygon_, u, v);
    }

private:
    const PatchPolygon& polygon_;
    std::uint64_t count_, state_, offset_, stride_, index_ = 0;
};

/// Unblocked fraction of `rays` segments from stratified points of the receiver to `rays` of the
/// shot's targets: every (count / rays)-th from a receiver-dependent start, visited in a
/// receiver-dependent stride order so that a receiver point's stratum and its target's stratum are
/// not correlated (the pairs must sample the receiver x shooter product, not its diagonal).
/// With memberWeight, a ray to member k counts memberWeight[k] (its unoccluded kernel per unit
/// power): the targets follow the power, the light arriving also follows the kernel, so members
/// below the receiver's horizon (floor beyond a block's corner, seen from its side; the rays run
/// into the block) and far members weigh what they send, not what they hold. A ray joining points
/// behind either's plane carries nothing and is not counted: from a patch's back it leaves through
/// the patch's own face, which no ray from its plane can hit (a closed double-sided sphere's inside
/// was lit so, 0.75% of its outside; 0.15% left, from pairs where no ray of the many faces). Returns
/// -1 when no ray joined facing parts, with the plain fraction of all rays in `plain`.
double stratifiedVisibility(const ShotGeometry& g, const ShotTargets& targets, std::size_t receiver,
                            const glm::dvec3& shooterNormal, int rays, std::uint64_t seed,
                            std::span<const double> memberWeight, double& plain) {
    const auto count = static_cast<std::uint64_t>(targets.points.size());
    const auto n = static_cast<std::uint64_t>(rays);
    const std::uint64_t spacing = std::max<std::uint64_t>(1, count / n);
    const std::uint64_t first = mix64(seed) % count;
    const std::uint64_t stride = coprimeStride(mix64(seed + 2), n);
    StratifiedOrigins origins(g.polygons[receiver], rays, mix64(seed + 3));
    double unblocked = 0, total = 0, unblockedBehind = 0, totalBehind = 0;
    for (std::uint64_t k = 0; k < n; ++k) {
        const std::uint64_t t = (first + ((stride * k) % n) * spacing) % count;
        const glm::dvec3 from = origins.next();
        const double weight = memberWeight.empty() ? 1.0 : memberWeight[targets.member[t]];
        if (weight <= 0) continue;
        const glm::dvec3 d = targets.points[t] - from;
        const glm::dvec3& targetNormal = targets.normal.empty() ? shooterNormal : targets.normal[t];
        const bool facing = glm::dot(g.polygons[receiver].normal, d) > 0 && glm::dot(targetNormal, d) < 0;
        const bool through = !g.rays->occluded(from, targets.points[t]);
        (facing ? total : totalBehind) += weight;
        if (through) (facing ? unblocked : unblockedBehind) += weight;
    }
    if (total > 0) return unblocked / total;
    // No ray joined parts in front of each other (a sliver of the pair): -1, with the plain fraction.
    plain = totalBehind > 0 ? unblockedBehind / totalBehind : 0.0;
    return -1;
}

/// Area-to-area visibility between the receiver and the shot's targets. A strong shot (the full
/// visibilityRays first) casts all targets.size() rays more at every receiver, and the two passes
/// are averaged with fixed weights: few rays alone would quantise a penumbra to {0, 1/2, 1} for the
/// whole solve (the light source shoots once). Stopping where the first rays agree would bias the
/// estimate towards 0 and 1 (with n independent first rays and a true fraction v it is
/// v^n + (1 - v^n - (1-v)^n) v' for the second pass's v': 3v^2 - 2v^3 for n = 2; with 16
/// stratified rays a receiver that sees a sliver of the light stays dark). Weaker shots cast their
/// fixed few rays, unbiased, and are averaged by the many shots after them.
double shotVisibility(const ShotGeometry& g, const ShotTargets& targets, std::size_t shooter, const glm::dvec3& shooterNormal,
                      std::size_t receiver, int fewRays, int penumbraRays, std::span<const double> memberWeight) {
    const std::uint64_t seed = pairSeed(g.options.seed, shooter, receiver);
    double plain = 0;
    const double first = stratifiedVisibility(g, targets, receiver, shooterNormal, fewRays, seed, memberWeight, plain);
    const bool more = penumbraRays > fewRays;
    if (first < 0) {  // none of the few rays weighed: the many find the facing parts, else the plain fraction
        if (!more) return plain;
        const double again =
            stratifiedVisibility(g, targets, receiver, shooterNormal, penumbraRays, mix64(seed ^ 0x5bd1e995ULL), memberWeight, plain);
        return again >= 0 ? again : plain;
    }
    // Whatever the first pass saw (see above: on the Cornell box stopping where it agreed left floor
    // patches in the short block's penumbra 25-30% dark at every seed).
    if (fewRays < g.options.visibilityRays || !more) return first;
    double unused = 0;
    double second =
        stratifiedVisibility(g, targets, receiver, shooterNormal, penumbraRays, mix64(seed ^ 0x5bd1e995ULL), memberWeight, unused);
    if (second < 0) second = first;
    return (first * fewRays + second * penumbraRays) / (fewRays + penumbraRays);
}

/// The kernel rule for a receiver whose gap to a polygon is at least `lowerBound` (m): the exact gap
/// is computed only where the bound alone does not settle the receiver as far.
const ReceiverRule& ruleFor(const PatchPolygon& receiver, const PatchPolygon& source, double lowerBound) {
    const double receiverDiameter = std::sqrt(2.0 * receiver.area);
    const double gap =
        lowerBound > kFarInDiameters * receiverDiameter ? lowerBound : distanceToPolygon(source, receiver.centroid);
    return gap > kFarInDiameters * receiverDiameter    ? kCentroid
           : gap > kNearInDiameters * receiverDiameter ? kGauss2
                                                       : kGauss4;
}

/// The unoccluded form factor from the receiver to the group as the shot leaves it: the group's
/// power share w_k on member k spread over that member, F = (A_group) sum_k (w_k / A_k) F_{r->k},
/// so that F times the group's mean unshot radiosity is the light each member sends. Treating the
/// group as uniform (the outline's kernel) is exact only when every member holds power in proportion
/// to its area; a block whose light sits on its near half (floor beside a box, the lit half of a
/// block's side) is otherwise lit as though its light sat at its centre (with the rays below, up to
/// 8.5% per surface and 51% per patch against Gauss-Seidel on the Cornell box at blocks of 3-4).
/// Per band: each band's light leaves from where that band's power is (bandShare).
Rgb unoccludedFromShot(const ShotGeometry& g, std::size_t shooter, std::size_t receiver, std::span<const double> memberShare,
                       std::span<const Rgb> bandShare, std::vector<double>& memberWeight) {
    const PatchPolygon& s = g.shooters[shooter];
    const PatchPolygon& r = g.polygons[receiver];
    const auto members = g.groups.group(shooter);
    memberWeight.clear();
    if (memberShare.empty() || members.size() == 1)
        return Rgb(receiverAverage(r, s, ruleFor(r, s, glm::length(r.centroid - s.centroid) - g.shooterRadius[shooter])));
    memberWeight.assign(members.size(), 0.0);
    // Members within kNearInDiameters of the receiver's diameter send their exact kernel averaged
    // over the receiver; the rest share what the outline's exact kernel, averaged over the
    // receiver, leaves after them, in the ratio of the kernels from the receiver's centroid to each
    // (a member's centroid for the member where it is far for its size). A uniform group gets the
    // outline's kernel exactly either way. A band held by the few members beside the receiver is
    // where the centroid's kernel is furthest from the receiver's average: with the ratio alone a
    // shot's closure was 1 - 0.034 for a corner member's band in a closed box (test "a block shot
    // keeps its power per band in a closed box"), and the Cornell box reflected 0.04-0.07 point
    // more light than Gauss-Seidel beyond what it does now (docs/ARCHITECTURE.md, session 19). A
    // shot costs a few flops per far member (an exact contour integral per member and Gauss point
    // made a shot ~10x slower).
    const double groupGap = glm::length(r.centroid - s.centroid) - g.shooterRadius[shooter];
    const double receiverDiameter = std::sqrt(2.0 * r.area);
    double nearKernel = 0, farByArea = 0;
    Rgb nearByPower(0.0), farByPower(0.0);
    for (std::size_t k = 0; k < members.size(); ++k) {
        const PatchPolygon& m = g.polygons[members[k]];
        const glm::dvec3 d = m.centroid - r.centroid;
        const double r2 = glm::dot(d, d);
        const double nearWithin = kNearInDiameters * receiverDiameter + g.patchRadius[members[k]];
        if (r2 < nearWithin * nearWithin) {
            // 2 x 2 points: in that closed box as close as 4 x 4 (closure within 0.03% against
            // 0.04%); on the Cornell box 4 x 4 cost +15% CPU, 2 x 2 -2% to +9% (medians, noisy runs).
            const double f = receiverAverage(r, m, kGauss2);
            memberWeight[k] = f / m.area;
            nearKernel += f;
            nearByPower += bandShare[k] * memberWeight[k];
            continue;
        }
        double kernel = 0;  // per unit area of the member
        if (r2 >= kRatioDistanceSquaredOverArea * m.area) {
            const double cosR = glm::dot(r.normal, d), cosM = -glm::dot(m.normal, d);
            kernel = cosR > 0 && cosM > 0 ? cosR * cosM / (std::numbers::pi * r2 * r2) : 0.0;
        } else {
            kernel = pointToPolygonFormFactor(r.centroid, r.normal, m.corners()) / m.area;
        }
        memberWeight[k] = -kernel;  // a far member's, scaled below (the sign marks it)
        farByArea += m.area * kernel;
        farByPower += bandShare[k] * kernel;
    }
    if (farByArea > 0) {
        const double scale = std::max(0.0, receiverAverage(r, s, ruleFor(r, s, groupGap)) - nearKernel) / farByArea;
        for (double& w : memberWeight)
            if (w < 0) w *= -scale;
        return (nearByPower + scale * farByPower) * s.area;
    }
    for (double& w : memberWeight) w = std::max(0.0, w);
    if (nearKernel > 0) return nearByPower * s.area;
    // The receiver's centroid sees none of the group's members (but its Gauss points may): each
    // member's kernel averaged over the receiver.
    Rgb sum(0.0);
    for (std::size_t k = 0; k < members.size(); ++k) {
        if (memberShare[k] <= 0) continue;
        const PatchPolygon& m = g.polygons[members[k]];
        const double lowerBound = glm::length(r.centroid - m.centroid) - g.patchRadius[members[k]];
        memberWeight[k] = receiverAverage(r, m, ruleFor(r, m, lowerBound)) / m.area;
        sum += bandShare[k] * memberWeight[k];
    }
    return sum * s.area;
}

/// The first pass's rays, a quarter of the penumbra count: all 16 for the light source's shot, whose
/// penumbra pass follows (shotVisibility), down to 2 (one a side of an edge) for weak shots, which
/// cast them alone.
int fewRaysFor(const ShotGeometry& g, int penumbraRays) {
    return std::clamp(penumbraRays / kPenumbraRayFactor, std::min(2, g.options.visibilityRays),
                      std::max(1, g.options.visibilityRays));
}

/// The penumbra ray count of a shot carrying `powerShare` of the emitted power (kFullPenumbraShare).
int penumbraRaysFor(const ShotTargets& targets, double powerShare) {
    const int most = static_cast<int>(targets.points.size());
    return std::clamp(static_cast<int>(std::ceil(most * std::min(1.0, std::abs(powerShare) / kFullPenumbraShare))), 1, most);
}

/// The visibility of a group's shot from a receiver whose rays to it disagreed (some blocked, some
/// not), resolved per member: sum_k p_k V_k with p_k = w_k K_k / sum_j w_j K_j (the member's power
/// share times its kernel per unit area at the receiver, memberWeight) and V_k the unblocked
/// fraction of n_k = round(rays p_k) segments from stratified points of the receiver to stratified
/// points of member k, drawn afresh for every shot of the group; members under one ray share
/// ceil(rays sum p) segments to points drawn by p. The shot's rays follow the power
/// alone, so where the kernel varies across the group (a receiver beside it) the few members that
/// carry most of the light get few of the rays. The unoccluded form factor, and so the power that
/// leaves the group, is untouched; only the fraction of it that arrives changes. A member no
/// segment reaches facing drops out of the sum. Returns `fallback` where no member does.
/// Per band, the same members' fractions weighed by that band's shares (the rays follow the band sum).
Rgb perMemberVisibility(const ShotGeometry& g, std::size_t shooter, std::uint32_t shot, std::size_t receiver,
                        std::span<const double> memberShare, std::span<const Rgb> bandShare,
                        std::span<const double> memberWeight, int rays, const Rgb& fallback) {
    const auto members = g.groups.group(shooter);
    double total = 0;
    Rgb bandTotal(0.0);
    for (std::size_t k = 0; k < members.size(); ++k) {
        total += memberShare[k] * memberWeight[k];
        bandTotal += bandShare[k] * memberWeight[k];
    }
    if (!(total > 0)) return fallback;
    const PatchPolygon& r = g.polygons[receiver];
    // shot + 1: the seeds these rays have always had (the count they read had been advanced by the
    // shot's targets), so the numbers measured in the docs and tests stay.
    const std::uint64_t seed = pairSeed(g.options.seed ^ 0x9e3779b97f4a7c15ULL, shooter * 1000003ULL + shot + 1, receiver);
    thread_local std::vector<glm::dvec3> to;
    Rgb sum(0.0), counted(0.0);
    // Member k's weight in each band, p_k per band (0 where the band holds no power).
    const auto bandP = [&](std::size_t k) {
        Rgb p(0.0);
        for (int b = 0; b < 3; ++b)
            if (bandTotal[b] > 0) p[b] = bandShare[k][b] * memberWeight[k] / bandTotal[b];
        return p;
    };
    // The unblocked fraction of n segments from stratified points of the receiver to the points `at`
    // gives, visited in a stride order so the receiver's u stratum and the target's are not paired;
    // -1 when none joins facing parts.
    // Each segment also counts in each band by the weight `at` gives it (its member's p in the band
    // over its p: the pooled segments are drawn by the band sum), the bands' fractions in `band`.
    const auto fraction = [&](int n, std::uint64_t pairsSeed, const auto& at, Rgb& band) {
        StratifiedOrigins fromPoints(r, n, pairsSeed);
        const auto count = static_cast<std::uint64_t>(n);
        const std::uint64_t stride = coprimeStride(mix64(pairsSeed + 2), count);
        const std::uint64_t offset = mix64(pairsSeed + 3) % count;
        int facing = 0, through = 0;
        Rgb bandFacing(0.0), bandThrough(0.0);
        for (std::uint64_t i = 0; i < count; ++i) {
            const glm::dvec3 from = fromPoints.next();
            const auto [target, normal, weight] = at((stride * i + offset) % count);
            const glm::dvec3 d = target - from;
            if (!(glm::dot(r.normal, d) > 0 && glm::dot(normal, d) < 0)) continue;
            ++facing;
            bandFacing += weight;
            if (!g.rays->occluded(from, target)) {
                ++through;
                bandThrough += weight;
            }
        }
        const double v = facing > 0 ? static_cast<double>(through) / facing : -1.0;
        for (int b = 0; b < 3; ++b) band[b] = bandFacing[b] > 0 ? bandThrough[b] / bandFacing[b] : v;
        return v;
    };
    // Members that would get a ray or more have their own; the rest share ceil(rays x their sum)
    // rays spread over them by p_k (one ray each for every member cost +60% of the Cornell box's solve).
    thread_local std::vector<double> pooled;  // cumulative p of the pooled members
    thread_local std::vector<std::uint32_t> pooledMember;
    pooled.clear();
    pooledMember.clear();
    double pool = 0;
    Rgb bandPool(0.0);
    for (std::size_t k = 0; k < members.size(); ++k) {
        const double p = memberShare[k] * memberWeight[k] / total;
        if (!(p > 0)) continue;
        if (rays * p < 1) {
            pool += p;
            bandPool += bandP(k);
            pooled.push_back(pool);
            pooledMember.push_back(static_cast<std::uint32_t>(k));
            continue;
        }
        const auto n = static_cast<int>(std::lround(rays * p));
        const PatchPolygon& m = g.polygons[members[k]];
        const std::uint64_t memberSeed = mix64(seed + 4 * k);
        StratifiedOrigins toPoints(m, n, mix64(memberSeed + 1));
        to.clear();
        for (int i = 0; i < n; ++i) to.push_back(toPoints.next());
        Rgb unused(0.0);
        const double v =
            fraction(n, memberSeed, [&](std::uint64_t i) { return std::tuple{to[i], m.normal, Rgb(1.0)}; }, unused);
        if (v < 0) continue;
        const Rgb bandWeight = bandP(k);
        sum += bandWeight * v;
        counted += bandWeight;
    }
    if (pool > 0) {
        const int n = std::max(1, static_cast<int>(std::ceil(rays * pool)));
        std::uint64_t state = mix64(seed + 4 * members.size());
        to.clear();
        thread_local std::vector<glm::dvec3> normals;
        thread_local std::vector<Rgb> weights;
        normals.clear();
        weights.clear();
        for (int i = 0; i < n; ++i) {  // stratified over the pooled members' cumulative p
            const double at = (i + nextUniform(state)) / n * pool;
            const std::size_t j = std::min<std::size_t>(
                pooled.size() - 1, static_cast<std::size_t>(std::upper_bound(pooled.begin(), pooled.end(), at) - pooled.begin()));
            const std::uint32_t k = pooledMember[j];
            const PatchPolygon& m = g.polygons[members[k]];
            to.push_back(pointOn(m, nextUniform(state), nextUniform(state)));
            normals.push_back(m.normal);
            weights.push_back(bandP(k) / (memberShare[k] * memberWeight[k] / total));
        }
        Rgb band(0.0);
        const double v = fraction(
            n, mix64(state), [&](std::uint64_t i) { return std::tuple{to[i], normals[i], weights[i]}; }, band);
        if (v >= 0) {
            sum += bandPool * band;
            counted += bandPool;
        }
    }
    Rgb visibility = fallback;
    for (int b = 0; b < 3; ++b)
        if (counted[b] > 0) visibility[b] = sum[b] / counted[b];
    return visibility;
}

Rgb receiverToShooter(const ShotGeometry& g, const ShotTargets& targets, std::size_t shooter, std::size_t receiver,
                      std::span<const double> memberShare, std::span<const Rgb> bandShare, int penumbraRays) {
    const PatchPolygon& s = g.shooters[shooter];
    const PatchPolygon& r = g.polygons[receiver];
    const Patch& pr = g.patches[receiver];
    // A shooter's own patches lie on its face, as do their coplanar neighbours: no exchange.
    if ((g.shooterSurface[shooter] == pr.surface && g.shooterFace[shooter] == pr.face) || cannotSeeEachOther(s, r))
        return Rgb(0.0);
    thread_local std::vector<double> memberWeight;
    const Rgb unoccluded = unoccludedFromShot(g, shooter, receiver, memberShare, bandShare, memberWeight);
    if (!(unoccluded.x + unoccluded.y + unoccluded.z > 0) || g.options.visibilityRays <= 0) return unoccluded;
    const int fewRays = fewRaysFor(g, penumbraRays);
    const double shot = shotVisibility(g, targets, shooter, s.normal, receiver, fewRays, penumbraRays, memberWeight);
    Rgb visibility(shot);
    // Only where the shot's rays disagreed, so a receiver that sees the whole group, or none of it,
    // costs nothing more; there the shot's visibility is resolved per member with as many rays
    // again as the receiver just cast (twice that was no better on the Cornell box: 0.72-0.74% off
    // Gauss-Seidel per patch against 0.78%, at +20% CPU against +10%), and per band. Where the rays
    // agree every band sees the group alike (all or none of it), so the rays above are not weighed
    // per band.
    if (shot > 0 && shot < 1 && !memberWeight.empty()) {
        const int cast = fewRays < g.options.visibilityRays || penumbraRays <= fewRays ? fewRays : fewRays + penumbraRays;
        visibility = perMemberVisibility(g, shooter, targets.shot, receiver, memberShare, bandShare, memberWeight, cast, visibility);
    }
    return unoccluded * visibility;
}

/// F_{receiver -> group} for a group of patches that need not be planar (PatchGroups.h), whose
/// radiosity is uniform, so each member sends in proportion to its area: the sum over its members
/// of each member's exact kernel averaged over the receiver (its own rule for its own gap), times
/// the visibility of rays to targets spread over the members by area, each ray weighed by its
/// member's kernel per unit area and facing judged by its member's normal. A member on the
/// receiver's own face, or wholly behind it, sends nothing.
double receiverToPatchGroup(const ShotGeometry& g, const ShotTargets& targets, std::size_t group, std::size_t receiver,
                            int penumbraRays) {
    const PatchPolygon& r = g.polygons[receiver];
    const Patch& pr = g.patches[receiver];
    const auto members = g.groups.group(group);
    thread_local std::vector<double> memberWeight;
    memberWeight.assign(members.size(), 0.0);
    double unoccluded = 0;
    for (std::size_t k = 0; k < members.size(); ++k) {
        const PatchPolygon& m = g.polygons[members[k]];
        const Patch& pm = g.patches[members[k]];
        if ((pm.surface == pr.surface && pm.face == pr.face) || cannotSeeEachOther(m, r)) continue;
        const double lowerBound = glm::length(r.centroid - m.centroid) - g.patchRadius[members[k]];
        const double f = receiverAverage(r, m, ruleFor(r, m, lowerBound));
        if (!(f > 0)) continue;
        memberWeight[k] = f / m.area;
        unoccluded += f;
    }
    if (unoccluded <= 0 || g.options.visibilityRays <= 0) return unoccluded;
    return unoccluded * shotVisibility(g, targets, group, glm::dvec3(0.0), receiver, fewRaysFor(g, penumbraRays),
                                       penumbraRays, memberWeight);
}

/// Each member's share of the shot's power (of the group's area when no power is given, or none
/// is positive); empty for a group of one patch.
std::vector<double> memberShares(const ShotGeometry& g, std::size_t shooter, std::span<const double> memberPower) {
    const auto members = g.groups.group(shooter);
    if (members.size() == 1) return {};
    double total = 0;
    if (memberPower.size() == members.size())
        for (const double w : memberPower) total += std::max(0.0, w);
    std::vector<double> share(members.size());
    for (std::size_t k = 0; k < members.size(); ++k)
        share[k] = total > 0 ? std::max(0.0, memberPower[k]) / total : g.polygons[members[k]].area / g.shooters[shooter].area;
    return share;
}

/// The same per band: member k's share of the band's power; a band with none takes the band
/// sum's shares (`share`), as its light is nil anyway.
std::vector<Rgb> memberBandShares(std::span<const Rgb> memberPower, std::span<const double> share) {
    if (share.empty()) return {};
    Rgb total(0.0);
    if (memberPower.size() == share.size())
        for (const Rgb& w : memberPower) total += glm::max(w, Rgb(0.0));
    std::vector<Rgb> band(share.size());
    for (std::size_t k = 0; k < share.size(); ++k)
        for (int b = 0; b < 3; ++b) band[k][b] = total[b] > 0 ? std::max(0.0, memberPower[k][b]) / total[b] : share[k];
    return band;
}

std::vector<double> bandSums(std::span<const Rgb> memberPower) {
    std::vector<double> sums(memberPower.size());
    for (std::size_t k = 0; k < sums.size(); ++k) sums[k] = memberPower[k].x + memberPower[k].y + memberPower[k].z;
    return sums;
}

} // namespace

ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options) {
    return makeRayCastShotFormFactors(scene, mesh, patchShooters(mesh), options);
}

ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                           const ProgressiveShooters& shooters, const SolverOptions& options) {
    GroupShotFormFactors byPower = makeRayCastGroupShotFormFactors(scene, mesh, shooters, options);
    auto bands = std::make_shared<std::vector<Rgb>>();  // called from one thread at a time
    return [byPower = std::move(byPower), bands](std::size_t shooter, std::uint32_t shot, std::span<double> toShooter) {
        bands->resize(toShooter.size());
        byPower(shooter, shot, {}, 1.0, *bands);  // without power every band leaves by area alike
        for (std::size_t j = 0; j < toShooter.size(); ++j) toShooter[j] = (*bands)[j].x;
    };
}

GroupShotFormFactors makeRayCastGroupShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                                     const ProgressiveShooters& shooters, const SolverOptions& options) {
    if (shooters.polygons.size() != shooters.size() || shooters.members.size() != mesh.size())
        throw RadiantError({scene.name, "progressive shooters"},
                           "the shooters need one outline per group (" + std::to_string(shooters.polygons.size()) +
                               " for " + std::to_string(shooters.size()) + " groups) and every patch once (" +
                               std::to_string(shooters.members.size()) + " of " + std::to_string(mesh.size()) + ")");
    auto geometry = std::make_shared<ShotGeometry>();
    geometry->polygons.resize(mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) geometry->polygons[i] = mesh.polygon(i);
    geometry->patches = mesh.patches;
    geometry->shooters = shooters.polygons;
    geometry->shooterSurface = shooters.surface;
    geometry->shooterFace = shooters.face;
    geometry->groups = shooters;
    for (const PatchPolygon& outline : shooters.polygons) geometry->shooterRadius.push_back(circumradius(outline));
    for (const PatchPolygon& patch : geometry->polygons) geometry->patchRadius.push_back(circumradius(patch));
    geometry->rays = options.rays ? options.rays : std::make_shared<const RayCaster>(scene);
    geometry->options = options.formFactors;
    geometry->options.seed = pairSeed(options.seed, options.formFactors.seed, 0);
    return [geometry](std::size_t shooter, std::uint32_t shot, std::span<const Rgb> memberPower, double powerShare,
                      std::span<Rgb> toShooter) {
        const std::vector<double> power = bandSums(memberPower);
        const ShotTargets targets = shotTargets(*geometry, shooter, shot, power, powerShare);
        const std::vector<double> share = memberShares(*geometry, shooter, power);
        const std::vector<Rgb> bandShare = memberBandShares(memberPower, share);
        const int penumbraRays = penumbraRaysFor(targets, powerShare);
        parallelFor(toShooter.size(), 256, [&](std::size_t begin, std::size_t end) {
            for (std::size_t j = begin; j < end; ++j)
                toShooter[j] = receiverToShooter(*geometry, targets, shooter, j, share, bandShare, penumbraRays);
        });
    };
}

GroupShotFormFactors makeRayCastPatchGroupShotFormFactors(const Scene& scene, const PatchMesh& mesh,
                                                          std::shared_ptr<const PatchGroups> groups,
                                                          const ProgressiveShooters& shooters, const SolverOptions& options) {
    if (!groups || groups->groupOf.size() != mesh.size() || shooters.members.size() != groups->size() ||
        shooters.polygons.size() != shooters.size() || shooters.surface.size() != shooters.size() ||
        shooters.face.size() != shooters.size())
        throw RadiantError({scene.name, "patch groups"}, "the groups or their shooters do not match the mesh");
    auto geometry = std::make_shared<ShotGeometry>();
    geometry->polygons.resize(mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) geometry->polygons[i] = mesh.polygon(i);
    geometry->patches = mesh.patches;
    for (const PatchPolygon& patch : geometry->polygons) geometry->patchRadius.push_back(circumradius(patch));
    // The shot geometry's groups are the shooters' patches: each shooter's groups' patches, in order.
    geometry->groups.first.push_back(0);
    for (std::size_t s = 0; s < shooters.size(); ++s) {
        for (const std::uint32_t group : shooters.group(s))
            for (const std::uint32_t p : groups->patchesOf(group)) geometry->groups.members.push_back(p);
        geometry->groups.first.push_back(static_cast<std::uint32_t>(geometry->groups.members.size()));
    }
    geometry->shooters = shooters.polygons;
    geometry->shooterSurface = shooters.surface;
    geometry->shooterFace = shooters.face;
    for (const PatchPolygon& outline : shooters.polygons) geometry->shooterRadius.push_back(circumradius(outline));
    geometry->rays = options.rays ? options.rays : std::make_shared<const RayCaster>(scene);
    geometry->options = options.formFactors;
    geometry->options.seed = pairSeed(options.seed, options.formFactors.seed, 0);
    auto perPatch = std::make_shared<std::vector<Rgb>>(mesh.size());
    return [geometry, groups = std::move(groups), shooterGroups = shooters, perPatch](
               std::size_t shooter, std::uint32_t shot, std::span<const Rgb> memberPower, double powerShare,
               std::span<Rgb> toShooter) {
        const ShotGeometry& g = *geometry;
        std::vector<Rgb>& f = *perPatch;
        if (g.shooters[shooter].count > 0) {
            // A planar block of groups (or one planar patch): the block kernel of the patch shooters,
            // each patch sending its group's share of the power spread over the group's area.
            const auto members = shooterGroups.group(shooter);
            std::vector<Rgb> patchPower;
            patchPower.reserve(g.groups.group(shooter).size());
            double total = 0;
            for (std::size_t k = 0; k < members.size(); ++k)
                if (memberPower.size() == members.size())
                    for (int b = 0; b < 3; ++b) total += std::max(0.0, memberPower[k][b]);
            for (std::size_t k = 0; k < members.size(); ++k) {
                const Rgb groupShare =
                    total > 0 ? glm::max(memberPower[k], Rgb(0.0)) / total : Rgb(groups->area[members[k]]);
                for (const std::uint32_t p : groups->patchesOf(members[k]))
                    patchPower.push_back(groupShare * (g.patches[p].area / groups->area[members[k]]));
            }
            const std::vector<double> power = bandSums(patchPower);
            const ShotTargets targets = shotTargets(*geometry, shooter, shot, power, powerShare);
            const std::vector<double> share = memberShares(g, shooter, power);
            const std::vector<Rgb> bandShare = memberBandShares(patchPower, share);
            const int penumbraRays = penumbraRaysFor(targets, powerShare);
            parallelFor(f.size(), 256, [&](std::size_t begin, std::size_t end) {
                for (std::size_t j = begin; j < end; ++j)
                    f[j] = receiverToShooter(g, targets, shooter, j, share, bandShare, penumbraRays);
            });
        } else {
            // One group that is not planar: its radiosity is uniform, so its light leaves its
            // members by area.
            ShotTargets targets = shotTargets(*geometry, shooter, shot, {}, powerShare);
            targets.normal.reserve(targets.member.size());
            const auto members = g.groups.group(shooter);
            for (const std::uint32_t k : targets.member) targets.normal.push_back(g.polygons[members[k]].normal);
            const int penumbraRays = penumbraRaysFor(targets, powerShare);
            parallelFor(f.size(), 64, [&](std::size_t begin, std::size_t end) {
                for (std::size_t j = begin; j < end; ++j) f[j] = Rgb(receiverToPatchGroup(g, targets, shooter, j, penumbraRays));
            });
        }
        // A receiving group gathers its patches' light by area: F_{D->S} = sum_{q in D} A_q F_{q->S} / A_D.
        std::fill(toShooter.begin(), toShooter.end(), Rgb(0.0));
        for (std::size_t q = 0; q < f.size(); ++q) toShooter[groups->groupOf[q]] += g.patches[q].area * f[q];
        for (std::size_t d = 0; d < toShooter.size(); ++d)
            toShooter[d] = groups->area[d] > 0 ? toShooter[d] / groups->area[d] : Rgb(0.0);
    };
}

} // namespace radiant
