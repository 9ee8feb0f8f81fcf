#include "app/ui/PlotAxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiant::app::ui {

LogAxis logAxisFor(std::span<const double> values, int maxTicks, int minDecades) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double v : values) {
        if (!(v > 0) || !std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    LogAxis axis;
    if (lo > hi) {
        lo = 0.1;
        hi = 1.0;
    }
    axis.lowExponent = static_cast<int>(std::floor(std::log10(lo)));
    axis.highExponent = static_cast<int>(std::ceil(std::log10(hi)));
    const int decades = std::max(1, minDecades);
    if (axis.highExponent - axis.lowExponent < decades) axis.highExponent = axis.lowExponent + decades;
    const int span = axis.highExponent - axis.lowExponent;
    int step = 1;
    for (const int candidate : {1, 2, 5, 10, 20, 50, 100}) {
        step = candidate;
        if (span / candidate + 1 <= std::max(1, maxTicks)) break;
    }
    // Ticks on multiples of the step, so that 1e0 stays a tick whenever it is on the axis.
    const int first = static_cast<int>(std::ceil(static_cast<double>(axis.lowExponent) / step)) * step;
    for (int e = first; e <= axis.highExponent; e += step) axis.tickExponents.push_back(e);
    return axis;
}

std::vector<double> linearTicks(double low, double high, int maxTicks, double minStep) {
    if (!(high > low) || !std::isfinite(low) || !std::isfinite(high)) return {low};
    const int count = std::max(1, maxTicks);
    double magnitude = std::pow(10.0, std::floor(std::log10((high - low) / count)));
    for (;;) {
        for (const double mantissa : {1.0, 2.0, 5.0}) {
            const double step = mantissa * magnitude;
            if (step < minStep) continue;
            const double first = std::ceil(low / step - 1e-9) * step;
            const auto n = static_cast<int>(std::floor((high - first) / step + 1e-9)) + 1;
            if (n <= count) {
                std::vector<double> ticks;
                for (int i = 0; i < n; ++i) ticks.push_back(first + i * step);
                if (ticks.empty()) ticks.push_back(low);
                return ticks;
            }
        }
        magnitude *= 10;
    }
}

} // namespace radiant::app::ui
