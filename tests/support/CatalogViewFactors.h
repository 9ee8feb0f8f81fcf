#pragma once
// View factors from Howell's catalog (as printed in docs/reference.md), written out
// once for every test that needs them as oracles. Independent of the code under test.
#include <cmath>
#include <numbers>

namespace radiant::test {

/// Parallel, directly opposed rectangles a x b at distance c.
inline double parallelRectangles(double a, double b, double c) {
    const double X = a / c, Y = b / c;
    const double X2 = X * X, Y2 = Y * Y;
    return 2 / (std::numbers::pi * X * Y) *
           (std::log(std::sqrt((1 + X2) * (1 + Y2) / (1 + X2 + Y2))) + X * std::sqrt(1 + Y2) * std::atan(X / std::sqrt(1 + Y2)) +
            Y * std::sqrt(1 + X2) * std::atan(Y / std::sqrt(1 + X2)) - X * std::atan(X) - Y * std::atan(Y));
}

/// Perpendicular rectangles w x l (from) and h x l (to) sharing the edge of length l.
inline double perpendicularRectangles(double w, double h, double l) {
    const double W = w / l, H = h / l;
    const double W2 = W * W, H2 = H * H, S = std::sqrt(H2 + W2);
    const double logTerm = std::log((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                           W2 * std::log(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                           H2 * std::log(H2 * (1 + W2 + H2) / ((1 + H2) * (W2 + H2)));
    return 1 / (std::numbers::pi * W) * (W * std::atan(1 / W) + H * std::atan(1 / H) - S * std::atan(1 / S) + 0.25 * logTerm);
}

/// Differential area to a parallel a x b rectangle whose corner lies on its normal at distance c.
inline double pointToCornerRectangle(double a, double b, double c) {
    const double A = a / c, B = b / c;
    return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
            B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
           (2 * std::numbers::pi);
}

/// Solid angle of a parallel a x b rectangle whose corner lies on the normal at distance h.
inline double cornerRectangleSolidAngle(double a, double b, double h) {
    return std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h)));
}

/// A quantity of the rectangle [x0, x1] x [y0, y1] at height h over the origin, from its
/// corner-rectangle formula g(a, b, h) by inclusion-exclusion over signed corner rectangles.
template <class CornerFormula>
double overRectangle(CornerFormula g, double x0, double x1, double y0, double y1, double h) {
    const auto signedCorner = [&](double x, double y) {
        const double value = g(std::abs(x), std::abs(y), h);
        return (x < 0) != (y < 0) ? -value : value;
    };
    return signedCorner(x1, y1) - signedCorner(x0, y1) - signedCorner(x1, y0) + signedCorner(x0, y0);
}

} // namespace radiant::test
