// Patch-to-patch form factor F(from -> to) = 1/A_from * integral over `from` of the exact
// point-to-polygon kernel (Lambert's contour integral) to `to`.
//
// The outer integral is Gauss-Legendre on `from`'s bilinear map (a triangle is the quad with its
// last corner doubled, i.e. the Duffy collapse, whose Jacobian vanishes on the collapsed edge). Far
// pairs get a fixed order chosen from distance over size. Near pairs - above all patches sharing an
// edge or a corner, where the kernel's derivatives blow up like log(distance to the edge) - are
// refined adaptively: each cell compares its rule with the two halvings (in u and in v) and is
// bisected in the direction that changed most, so refinement concentrates in thin strips along a
// shared edge instead of a quadtree; the cell with the largest error is split next, until the
// errors sum to the tolerance.
//
// Quadrature with an analytic inner kernel: Schroeder & Hanrahan, "On the form factor between two
// polygons", SIGGRAPH 1993 (discussion of the log singularity of adjacent polygons); Baum,
// Rushmeier & Winget, SIGGRAPH 1989.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/formfactor/LambertKernel.h"

namespace radiant {
namespace {

constexpr int kMaxGaussOrder = 8;

/// Gauss-Legendre nodes and weights mapped to [0, 1].
struct GaussRule {
    std::array<double, kMaxGaussOrder> node{};
    std::array<double, kMaxGaussOrder> weight{};
    int order = 0;
};

GaussRule makeGaussRule(int order) {
    GaussRule rule;
    rule.order = order;
    for (int i = 0; i < order; ++i) {
        // Newton's iteration on P_order from Tricomi's initial guess.
        double z = std::cos(std::numbers::pi * (i + 0.75) / (order + 0.5));
        double derivative = 1;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1;
            double p1 = z;
            for (int k = 2; k <= order; ++k) {
                const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = order * (z * p1 - p0) / (z * z - 1);
            const double step = p1 / derivative;
            z -= step;
            if (std::abs(step) < 1e-16) break;
        }
        rule.node[static_cast<std::size_t>(i)] = 0.5 * (1 - z);
        rule.weight[static_cast<std::size_t>(i)] = 1.0 / ((1 - z * z) * derivative * derivative);
    }
    return rule;
}

const GaussRule& gaussRule(int order) {
    static const std::array<GaussRule, kMaxGaussOrder + 1> rules = [] {
        std::array<GaussRule, kMaxGaussOrder + 1> all{};
        for (int n = 1; n <= kMaxGaussOrder; ++n) all[static_cast<std::size_t>(n)] = makeGaussRule(n);
        return all;
    }();
    return rules[static_cast<std::size_t>(std::clamp(order, 1, kMaxGaussOrder))];
}

struct Cell {
    double u0, u1, v0, v1;
};

/// A convex triangle or quad over which the outer integral runs: `from`, or one of the (at most
/// two) pieces of the part of `from` in front of `to`'s plane.
struct FrontPiece {
    std::array<glm::dvec3, 4> corners{};
    std::size_t count = 0;
};

/// The part of `from` in front of `to`'s plane, cut into a triangle or quad plus possibly one more
/// triangle. Behind that plane the kernel is zero, and the kink where it reaches zero would ruin the
/// quadrature's convergence, so the integral runs over the front part only.
std::size_t frontPieces(const PatchPolygon& from, const PatchPolygon& to, double tolerance, std::array<FrontPiece, 2>& pieces) {
    std::array<glm::dvec3, 5> clipped{};
    std::size_t count = 0;
    // Corners within `tolerance` of the plane lie on it: a shared edge is not cut off.
    const auto height = [&](const glm::dvec3& p) {
        const double h = glm::dot(to.normal, p - to.centroid);
        return std::abs(h) <= tolerance ? 0.0 : h;
    };
    glm::dvec3 start = from.vertices[from.count - 1];
    double startHeight = height(start);
    for (std::size_t i = 0; i < from.count; ++i) {
        const glm::dvec3& end = from.vertices[i];
        const double endHeight = height(end);
        if ((startHeight > 0 && endHeight < 0) || (startHeight < 0 && endHeight > 0))
            clipped[count++] = start + (end - start) * (startHeight / (startHeight - endHeight));
        if (endHeight >= 0) clipped[count++] = end;
        start = end;
        startHeight = endHeight;
    }
    if (count < 3) return 0;
    pieces[0].count = std::min<std::size_t>(count, 4);
    std::copy_n(clipped.begin(), pieces[0].count, pieces[0].corners.begin());
    if (count < 5) return 1;
    pieces[1].count = 3;
    pieces[1].corners = {clipped[0], clipped[3], clipped[4], glm::dvec3(0.0)};
    return 2;
}

/// A triangle's corners rotated so that the corner farthest from `target` comes last: the Duffy
/// collapse then sits away from where the kernel is singular (an edge shared with `to`).
FrontPiece collapseFarthestCorner(FrontPiece piece, const glm::dvec3& target) {
    if (piece.count != 3) return piece;
    std::size_t farthest = 0;
    double farthestDistance = -1;
    for (std::size_t i = 0; i < 3; ++i) {
        const glm::dvec3 d = piece.corners[i] - target;
        if (glm::dot(d, d) > farthestDistance) {
            farthestDistance = glm::dot(d, d);
            farthest = i;
        }
    }
    std::rotate(piece.corners.begin(), piece.corners.begin() + static_cast<std::ptrdiff_t>(farthest + 1),
                piece.corners.begin() + 3);
    return piece;
}

/// The integrand over a piece's parameter square: the kernel times the bilinear map's Jacobian (a
/// triangle is the quad with its last corner doubled).
class FromToIntegrand {
public:
    FromToIntegrand(const FrontPiece& piece, const glm::dvec3& normal, const PatchPolygon& to)
        : FromToIntegrand(collapseFarthestCorner(piece, to.centroid), normal, to, 0) {}

    /// Integral of kernel * dA over the cell with the Gauss rule, in m^2.
    [[nodiscard]] double integrate(const Cell& cell, const GaussRule& rule) const {
        const double du = cell.u1 - cell.u0;
        const double dv = cell.v1 - cell.v0;
        const glm::dvec3 alongUBottom = b_ - a_;
        const glm::dvec3 alongUTop = c_ - d_;
        double sum = 0;
        for (int i = 0; i < rule.order; ++i) {
            const double u = cell.u0 + du * rule.node[static_cast<std::size_t>(i)];
            // Along v at fixed u the map is a straight segment from bottom(u) to top(u).
            const glm::dvec3 bottom = a_ + alongUBottom * u;
            const glm::dvec3 alongV = d_ + alongUTop * u - bottom;
            double rowSum = 0;
            for (int j = 0; j < rule.order; ++j) {
                const double v = cell.v0 + dv * rule.node[static_cast<std::size_t>(j)];
                const glm::dvec3 x = bottom + alongV * v;
                const glm::dvec3 alongU = alongUBottom + (alongUTop - alongUBottom) * v;
                const double jacobian = glm::dot(normal_, glm::cross(alongU, alongV));
                const double kernel = detail::formFactorFromLambertSum(
                    detail::clippedLambertSum(x, normal_, to_.vertices, to_.count));
                rowSum += rule.weight[static_cast<std::size_t>(j)] * jacobian * kernel;
            }
            sum += rule.weight[static_cast<std::size_t>(i)] * rowSum;
        }
        return sum * du * dv;
    }

private:
    FromToIntegrand(const FrontPiece& piece, const glm::dvec3& normal, const PatchPolygon& to, int)
        : a_(piece.corners[0]), b_(piece.corners[1]), c_(piece.corners[2]),
          d_(piece.count == 4 ? piece.corners[3] : piece.corners[2]), normal_(normal), to_(to) {}

    glm::dvec3 a_, b_, c_, d_, normal_;
    const PatchPolygon& to_;
};

/// Largest height of `polygon`'s corners above the plane through `point` with normal `normal`.
double maxHeightAbove(const PatchPolygon& polygon, const glm::dvec3& point, const glm::dvec3& normal) {
    double h = -1e300;
    for (std::size_t i = 0; i < polygon.count; ++i) h = std::max(h, glm::dot(normal, polygon.vertices[i] - point));
    return h;
}

// Pairs closer than this (centroid distance over the sum of circumradii) may touch and are refined
// adaptively; touching polygons always have a ratio <= 1.
constexpr double kAdaptiveSeparation = 1.5;
constexpr int kAdaptiveOrder = 3;
constexpr std::size_t kMaxCells = 256;
constexpr double kSmallFormFactor = 1e-3;

/// A cell of the adaptive quadrature with its Gauss estimate refined by halving in u or in v,
/// whichever changed it more, and that change as its error estimate.
struct AdaptiveCell {
    Cell cell;
    double value = 0;
    double error = 0;
    bool splitU = true;
    std::array<double, 2> halves{};  ///< estimates of the two halves in the chosen direction
};

AdaptiveCell assess(const FromToIntegrand& integrand, const GaussRule& rule, const Cell& cell, double estimate) {
    const double uMid = 0.5 * (cell.u0 + cell.u1);
    const double vMid = 0.5 * (cell.v0 + cell.v1);
    const std::array<double, 2> alongU{integrand.integrate({cell.u0, uMid, cell.v0, cell.v1}, rule),
                                       integrand.integrate({uMid, cell.u1, cell.v0, cell.v1}, rule)};
    const std::array<double, 2> alongV{integrand.integrate({cell.u0, cell.u1, cell.v0, vMid}, rule),
                                       integrand.integrate({cell.u0, cell.u1, vMid, cell.v1}, rule)};
    const double changeU = std::abs(alongU[0] + alongU[1] - estimate);
    const double changeV = std::abs(alongV[0] + alongV[1] - estimate);
    AdaptiveCell assessed;
    assessed.cell = cell;
    assessed.splitU = changeU >= changeV;
    assessed.halves = assessed.splitU ? alongU : alongV;
    assessed.value = assessed.halves[0] + assessed.halves[1];
    assessed.error = std::max(changeU, changeV);
    return assessed;
}

/// Globally adaptive (as QUADPACK's qag, in two dimensions): keep splitting the cell with the
/// largest error estimate until the estimates sum to the tolerance. A local tolerance halved per
/// split would never be met at the end of a shared edge, where the error only falls like the area.
double integrateAdaptively(const FromToIntegrand& integrand, const GaussRule& rule, double estimate, double tolerance) {
    std::array<AdaptiveCell, kMaxCells> cells;
    std::size_t count = 1;
    cells[0] = assess(integrand, rule, {0, 1, 0, 1}, estimate);
    double totalError = cells[0].error;
    while (totalError > tolerance && count + 1 <= cells.size()) {
        std::size_t worst = 0;
        for (std::size_t i = 1; i < count; ++i)
            if (cells[i].error > cells[worst].error) worst = i;
        const AdaptiveCell parent = cells[worst];
        const Cell& c = parent.cell;
        const double uMid = 0.5 * (c.u0 + c.u1);
        const double vMid = 0.5 * (c.v0 + c.v1);
        const Cell first = parent.splitU ? Cell{c.u0, uMid, c.v0, c.v1} : Cell{c.u0, c.u1, c.v0, vMid};
        const Cell second = parent.splitU ? Cell{uMid, c.u1, c.v0, c.v1} : Cell{c.u0, c.u1, vMid, c.v1};
        cells[worst] = assess(integrand, rule, first, parent.halves[0]);
        cells[count++] = assess(integrand, rule, second, parent.halves[1]);
        totalError += cells[worst].error + cells[count - 1].error - parent.error;
    }
    double value = 0;
    for (std::size_t i = 0; i < count; ++i) value += cells[i].value;
    return value;
}

/// Gauss order for a pair separated by `separation` (centroid distance over the sum of
/// circumradii): the quadrature error falls roughly like (1 / (2 separation))^(2 order).
int orderForSeparation(double separation, double accuracy) {
    const double ratio = 0.5 / separation;
    const double order = std::log(std::max(accuracy, 1e-15) * 0.01) / (2 * std::log(ratio));
    return std::clamp(static_cast<int>(std::ceil(order)), 1, kMaxGaussOrder);
}

void checkPolygon(const PatchPolygon& polygon, const char* which) {
    if (polygon.count != 3 && polygon.count != 4)
        throw RadiantError({"formFactor", which},
                           "a patch polygon has 3 or 4 corners, got " + std::to_string(polygon.count));
    if (!(polygon.area > 0))
        throw RadiantError({"formFactor", which}, "a patch polygon needs a positive area, got " +
                                                      std::to_string(polygon.area) + " m^2");
}

} // namespace

double unoccludedFormFactor(const PatchPolygon& from, const PatchPolygon& to, double accuracy) {
    checkPolygon(from, "from");
    checkPolygon(to, "to");
    const double radiusFrom = circumradius(from);
    const double radiusTo = circumradius(to);
    // Nothing of `to` above `from`'s plane, or nothing of `from` in front of `to`: no exchange.
    // This also settles coplanar neighbours exactly, and a double-sided face's twins, which lie in
    // each other's plane only to the faces' planarity.
    const double inPlane = planarityTolerance(from, to);
    if (maxHeightAbove(to, from.centroid, from.normal) <= inPlane || maxHeightAbove(from, to.centroid, to.normal) <= inPlane)
        return 0.0;
    const double planeTolerance = 1e-9 * (radiusFrom + radiusTo);

    std::array<FrontPiece, 2> pieces;
    const std::size_t pieceCount = frontPieces(from, to, planeTolerance, pieces);
    const Cell whole{0, 1, 0, 1};
    const double separation = glm::length(to.centroid - from.centroid) / (radiusFrom + radiusTo);
    double integral = 0;  // m^2
    if (separation >= kAdaptiveSeparation) {
        const GaussRule& rule = gaussRule(orderForSeparation(separation, accuracy));
        for (std::size_t p = 0; p < pieceCount; ++p) integral += FromToIntegrand(pieces[p], from.normal, to).integrate(whole, rule);
        return integral / from.area;
    }
    const GaussRule& rule = gaussRule(kAdaptiveOrder);
    std::array<double, 2> estimates{};
    double total = 0;
    for (std::size_t p = 0; p < pieceCount; ++p) {
        estimates[p] = FromToIntegrand(pieces[p], from.normal, to).integrate(whole, rule);
        total += std::abs(estimates[p]);
    }
    // Aim well inside the requested accuracy (error estimates are themselves estimates): relative
    // for F above kSmallFormFactor, absolute below, so a sliver of a pair does not refine for ever
    // over an F that no row sum will notice.
    const double tolerance = 0.25 * accuracy * std::max(total, kSmallFormFactor * from.area) /
                             static_cast<double>(std::max<std::size_t>(pieceCount, 1));
    for (std::size_t p = 0; p < pieceCount; ++p)
        integral += integrateAdaptively(FromToIntegrand(pieces[p], from.normal, to), rule, estimates[p], tolerance);
    return std::max(0.0, integral) / from.area;
}

double formFactor(const PatchPolygon& from, const PatchPolygon& to, const RayCaster* rays,
                  const FormFactorOptions& options) {
    const double unoccluded = unoccludedFormFactor(from, to, options.accuracy);
    if (unoccluded == 0 || rays == nullptr || options.visibilityRays <= 0) return unoccluded;
    return unoccluded * visibilityFraction(from, to, rays, options);
}

} // namespace radiant
