#include "radiometry/galerkin/Quadrature.h"

#include <cmath>
#include <numbers>

#include "radiometry/common/Check.h"

namespace radiant::galerkin {

QuadratureRule gaussLegendreOnUnitInterval(std::size_t n) {
    RADIANT_CHECK_GE(n, std::size_t{1});
    // Newton on P_n from Chebyshev-like starting guesses (Numerical Recipes' gauleg): converges to
    // round-off in a few steps for any n used here (<= 64).
    QuadratureRule rule(n);
    for (std::size_t i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (static_cast<double>(n) + 0.5));
        double derivative = 0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1, p1 = 0;
            for (std::size_t j = 1; j <= n; ++j) {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * static_cast<double>(j) - 1) * x * p1 - (static_cast<double>(j) - 1) * p2) / static_cast<double>(j);
            }
            derivative = static_cast<double>(n) * (x * p0 - p1) / (x * x - 1);
            const double step = p0 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        // On [-1, 1] the weight is 2 / ((1 - x^2) P_n'(x)^2); on [0, 1] half of it.
        const double weight = 1.0 / ((1 - x * x) * derivative * derivative);
        rule[i] = {{0.5 * (1 - x), 0}, weight};
        rule[n - 1 - i] = {{0.5 * (1 + x), 0}, weight};
    }
    return rule;
}

QuadratureRule tensorGaussSquareRule(std::size_t n) {
    const QuadratureRule line = gaussLegendreOnUnitInterval(n);
    QuadratureRule rule;
    rule.reserve(n * n);
    for (const QuadratureNode& a : line)
        for (const QuadratureNode& b : line) rule.push_back({{a.at.u, b.at.u}, a.weight * b.weight});
    return rule;
}

QuadratureRule triangleRule3() {
    return {{{1.0 / 6, 1.0 / 6}, 1.0 / 3}, {{2.0 / 3, 1.0 / 6}, 1.0 / 3}, {{1.0 / 6, 2.0 / 3}, 1.0 / 3}};
}

QuadratureRule triangleRule7() {
    // Radon (1948), as in Stroud T2:5-1: the centroid and two orbits of three.
    const double s15 = std::sqrt(15.0);
    const double a1 = (6 - s15) / 21, a2 = (6 + s15) / 21;
    const double w1 = (155 - s15) / 1200, w2 = (155 + s15) / 1200;
    // Weights as shares of the triangle (9/40 + 3 w1 + 3 w2 = 1).
    return {{{1.0 / 3, 1.0 / 3}, 9.0 / 40},
            {{a1, a1}, w1}, {{1 - 2 * a1, a1}, w1}, {{a1, 1 - 2 * a1}, w1},
            {{a2, a2}, w2}, {{1 - 2 * a2, a2}, w2}, {{a2, 1 - 2 * a2}, w2}};
}

QuadratureRule collapsedGaussTriangleRule(std::size_t n) {
    const QuadratureRule line = gaussLegendreOnUnitInterval(n);
    QuadratureRule rule;
    rule.reserve(n * n);
    for (const QuadratureNode& s : line)
        for (const QuadratureNode& t : line)
            rule.push_back({{s.at.u, (1 - s.at.u) * t.at.u}, 2 * (1 - s.at.u) * s.weight * t.weight});
    return rule;
}

QuadratureRule elementRule(ElementShape shape, std::size_t level) {
    RADIANT_CHECK_GE(level, std::size_t{2});
    if (shape == ElementShape::Quad) return tensorGaussSquareRule(level);
    if (level == 2) return triangleRule3();
    if (level == 3) return triangleRule7();
    return collapsedGaussTriangleRule(level);
}

} // namespace radiant::galerkin
