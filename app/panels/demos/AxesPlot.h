#pragma once
// A small line plot for the demos' panels with what ImGui's PlotLines lacks: axes with ticks and
// numbers, a unit on each, linear or log scales, and the curve clipped to the frame.
#include <vector>

namespace radiant::app {

struct PlotAxis {
    double lo = 0, hi = 1;
    bool log = false;
    const char* title = "";       ///< the quantity and its unit, under the x axis / above the y axis
    std::vector<double> ticks;    ///< values marked and numbered (%g)
};

/// Fills the panel's width, `heightInFonts` font sizes tall; xs and ys of the same length. A finite
/// `markerX` draws a vertical line there: where the sliders stand now.
void drawAxesPlot(const std::vector<double>& xs, const std::vector<double>& ys, const PlotAxis& x,
                  const PlotAxis& y, double markerX, float heightInFonts = 8.0f);

} // namespace radiant::app
