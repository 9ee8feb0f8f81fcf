// The display's tone curve table against the closed forms it tabulates: Narkowicz's ACES fit and
// the sRGB transfer function, written out here independently of render/ColourScale.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/ColourScale.h"

namespace {
double aces(double x) { return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
double srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }
} // namespace

TEST_CASE("tone curve table: within 1e-5 of the ACES fit and sRGB encoding from black to beyond white") {
    const radiant::render::ToneCurveTable curve;
    double worst = 0, worstAt = 0;
    // Dense and log-spaced: the curve is steepest near 0, where sRGB's linear toe meets its power law.
    for (double x = 1e-7; x < 20.0; x *= 1.0005) {
        const double error = std::abs(curve(x) - srgb(aces(x)));
        if (error > worst) {
            worst = error;
            worstAt = x;
        }
    }
    CAPTURE(worstAt);
    CHECK(worst < 1e-5);  // 2.4e-6 expected at 4096 entries; 1024 would give 2.2e-5
    CHECK(curve(0.0) == 0.0f);
    CHECK(curve(-1.0) == 0.0f);
    CHECK(curve(std::numeric_limits<double>::quiet_NaN()) == 0.0f);
    CHECK(curve(1e9) == 1.0f);
    // Where the fit first reaches 1 (the table's end): just below it the curve is still under 1.
    CHECK(aces(radiant::render::ToneCurveTable::kSaturation) == doctest::Approx(1.0).epsilon(1e-4).scale(0));
    CHECK(aces(radiant::render::ToneCurveTable::kSaturation * 0.9) < 1.0);
}
