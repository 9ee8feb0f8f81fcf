#include "render/ColourScale.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace radiant::render {

double acesFitted(double x) {
    x = std::max(x, 0.0);
    return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

double linearToSrgb(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

ToneCurveTable::ToneCurveTable() {
    for (int i = 0; i <= kEntries; ++i) {
        const double u = static_cast<double>(i) / kEntries;
        entries_[i] = static_cast<float>(linearToSrgb(acesFitted(u * u * kSaturation)));
    }
}

float ToneCurveTable::operator()(double x) const {
    if (!(x > 0)) return 0.0f;  // also NaN: black, as acesFitted's clamp gives
    if (x >= kSaturation) return 1.0f;
    const double at = std::sqrt(x / kSaturation) * kEntries;
    const auto i = std::min(static_cast<int>(at), kEntries - 1);
    const auto f = static_cast<float>(at - i);
    return entries_[i] + f * (entries_[i + 1] - entries_[i]);
}

glm::dvec3 viridis(double t) {
    // matplotlib's viridis at t = 0, 1/8, ..., 1, sRGB-encoded bytes.
    static constexpr std::array<std::array<double, 3>, 9> table{{{68, 1, 84},
                                                                 {71, 45, 123},
                                                                 {59, 82, 139},
                                                                 {44, 114, 142},
                                                                 {33, 145, 140},
                                                                 {40, 174, 128},
                                                                 {94, 201, 98},
                                                                 {173, 220, 48},
                                                                 {253, 231, 37}}};
    const double s = std::clamp(t, 0.0, 1.0) * 8.0;
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(s), 7);
    const double f = s - static_cast<double>(i);
    const glm::dvec3 a(table[i][0], table[i][1], table[i][2]);
    const glm::dvec3 b(table[i + 1][0], table[i + 1][1], table[i + 1][2]);
    return (a + (b - a) * f) / 255.0;
}

double ColourLegend::position(double valueW_m2) const {
    double t = 0;
    if (logScale) {
        const double lo = std::log10(minW_m2), hi = std::log10(maxW_m2);
        t = valueW_m2 > 0 ? (std::log10(valueW_m2) - lo) / (hi - lo) : 0.0;
    } else {
        t = (valueW_m2 - minW_m2) / (maxW_m2 - minW_m2);
    }
    return std::clamp(t, 0.0, 1.0);
}

double ColourLegend::linearStepW_m2() const {
    if (logScale) return 0;
    return ticksW_m2.size() >= 2 ? ticksW_m2[1] - ticksW_m2[0] : maxW_m2 - minW_m2;
}

double ColourLegend::isolineCoordinate(double t) const {
    if (!logScale) {
        const double step = linearStepW_m2();
        return (minW_m2 + t * (maxW_m2 - minW_m2)) / step;
    }
    const double lo = std::log10(minW_m2), hi = std::log10(maxW_m2);
    const double exponent = lo + t * (hi - lo);
    const double decade = std::floor(exponent);
    const double mantissa = std::pow(10.0, exponent - decade);  // in [1, 10)
    const double piece = mantissa < 2 ? mantissa - 1 : mantissa < 5 ? 1 + (mantissa - 2) / 3 : 2 + (mantissa - 5) / 5;
    return 3 * decade + piece;
}

std::string formatLegendTick(double valueW_m2) {
    char text[32];
    if (valueW_m2 == 0) return "0";
    const double magnitude = std::abs(valueW_m2);
    if (magnitude >= 1e4 && magnitude < 1e7) std::snprintf(text, sizeof text, "%gk", valueW_m2 / 1e3);
    else std::snprintf(text, sizeof text, "%g", valueW_m2);
    return text;
}

namespace {

/// The smallest of 1, 2, 5 x 10^k that is at least `value`.
double niceStepAtLeast(double value) {
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= value * (1 - 1e-9)) return m * decade;
    return 10.0 * decade;
}

} // namespace

ColourLegend makeLegend(double maxW_m2, bool logScale, int decades) {
    ColourLegend legend;
    legend.logScale = logScale;
    legend.maxW_m2 = maxW_m2 > 0 && std::isfinite(maxW_m2) ? maxW_m2 : 1.0;
    if (logScale) {
        legend.minW_m2 = legend.maxW_m2 * std::pow(10.0, -std::max(decades, 1));
        // 1, 2 and 5 of every decade inside the range (both ends included when they land on one):
        // three decades of powers of ten alone left the isolines too far apart to read a value.
        const int firstDecade = static_cast<int>(std::floor(std::log10(legend.minW_m2) + 1e-9));
        const int lastDecade = static_cast<int>(std::floor(std::log10(legend.maxW_m2) + 1e-9));
        for (int k = firstDecade; k <= lastDecade; ++k)
            for (const double m : {1.0, 2.0, 5.0}) {
                const double tick = m * std::pow(10.0, k);
                if (tick >= legend.minW_m2 * (1 - 1e-9) && tick <= legend.maxW_m2 * (1 + 1e-9)) legend.ticksW_m2.push_back(tick);
            }
    } else {
        legend.minW_m2 = 0;
        // Four to ten ticks at a 1-2-5 step.
        const double step = niceStepAtLeast(legend.maxW_m2 / 8.0);
        for (int k = 0; static_cast<double>(k) * step <= legend.maxW_m2 * (1 + 1e-9); ++k)
            legend.ticksW_m2.push_back(static_cast<double>(k) * step);
    }
    return legend;
}

} // namespace radiant::render
