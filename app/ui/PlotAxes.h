#pragma once
// Axis ranges and ticks for the lab's plots, without ImGui or GL (unit-tested alone): a log10 axis
// over whole decades, ticked at decades (every second or fifth one when they would crowd), and a
// linear axis ticked at 1-2-5 steps.
#include <span>
#include <vector>

namespace radiant::app::ui {

/// A log10 axis from 10^lowExponent to 10^highExponent (whole decades, low < high).
struct LogAxis {
    int lowExponent = -1;
    int highExponent = 0;
    std::vector<int> tickExponents;  ///< labelled "1e<n>"
};

/// The whole decades that hold every positive finite value (others are skipped), at least
/// `minDecades` of them; at most `maxTicks` ticks. No usable value gives 1e-1 .. 1e0.
[[nodiscard]] LogAxis logAxisFor(std::span<const double> values, int maxTicks, int minDecades = 1);

/// Ticks at multiples of 1, 2 or 5 times a power of ten within [low, high], at most `maxTicks` of
/// them (at least one: the step grows until they fit), the step at least `minStep` (1 for counts
/// such as iterations, which have no tick between 1 and 2). high <= low gives {low}.
[[nodiscard]] std::vector<double> linearTicks(double low, double high, int maxTicks, double minStep = 0);

} // namespace radiant::app::ui
