#include "app/panels/demos/AxesPlot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radiant::app {
namespace {

/// Where a value sits along an axis, 0 at lo and 1 at hi.
double fraction(const PlotAxis& axis, double v) {
    if (axis.log) return (std::log10(std::max(v, 1e-300)) - std::log10(axis.lo)) / (std::log10(axis.hi) - std::log10(axis.lo));
    return (v - axis.lo) / (axis.hi - axis.lo);
}

} // namespace

void drawAxesPlot(const std::vector<double>& xs, const std::vector<double>& ys, const PlotAxis& x,
                  const PlotAxis& y, double markerX, float heightInFonts) {
    const float font = ImGui::GetFontSize();
    char text[32];
    float tickLabelWidth = 0;
    for (const double t : y.ticks) {
        std::snprintf(text, sizeof text, "%.3g", t);
        tickLabelWidth = std::max(tickLabelWidth, ImGui::CalcTextSize(text).x);
    }
    ImGui::TextDisabled("%s", y.title);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = font * heightInFonts;
    ImGui::Dummy({width, height});
    // The frame: room on the left for the y numbers, below for the x numbers and the x title.
    const ImVec2 lo{origin.x + tickLabelWidth + 0.5f * font, origin.y + 0.5f * font};
    const ImVec2 hi{origin.x + width - 0.8f * font, origin.y + height - 2.4f * font};
    if (hi.x <= lo.x || hi.y <= lo.y) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 axisColour = ImGui::GetColorU32(ImGuiCol_TextDisabled), textColour = ImGui::GetColorU32(ImGuiCol_Text);
    const auto screen = [&](double vx, double vy) {
        return ImVec2{lo.x + static_cast<float>(fraction(x, vx)) * (hi.x - lo.x),
                      hi.y - static_cast<float>(fraction(y, vy)) * (hi.y - lo.y)};
    };
    draw->AddRect(lo, hi, axisColour);
    for (const double t : x.ticks) {
        const float px = screen(t, y.lo).x;
        draw->AddLine({px, hi.y}, {px, hi.y + 0.3f * font}, axisColour);
        std::snprintf(text, sizeof text, "%.3g", t);
        const float w = ImGui::CalcTextSize(text).x;
        draw->AddText({std::clamp(px - 0.5f * w, origin.x, origin.x + width - w), hi.y + 0.35f * font}, textColour, text);
    }
    for (const double t : y.ticks) {
        const float py = screen(x.lo, t).y;
        draw->AddLine({lo.x - 0.3f * font, py}, {lo.x, py}, axisColour);
        std::snprintf(text, sizeof text, "%.3g", t);
        const ImVec2 size = ImGui::CalcTextSize(text);
        draw->AddText({lo.x - 0.4f * font - size.x, py - 0.5f * size.y}, textColour, text);
    }
    const float titleWidth = ImGui::CalcTextSize(x.title).x;
    draw->AddText({std::max(origin.x, 0.5f * (lo.x + hi.x - titleWidth)), hi.y + 1.3f * font}, axisColour, x.title);
    draw->PushClipRect(lo, hi, true);
    for (std::size_t i = 0; i + 1 < std::min(xs.size(), ys.size()); ++i)
        draw->AddLine(screen(xs[i], ys[i]), screen(xs[i + 1], ys[i + 1]), ImGui::GetColorU32(ImGuiCol_PlotLines), 2.0f);
    if (std::isfinite(markerX)) {
        const float px = screen(markerX, y.lo).x;
        draw->AddLine({px, lo.y}, {px, hi.y}, ImGui::GetColorU32(ImGuiCol_PlotLinesHovered), 1.5f);
    }
    draw->PopClipRect();
}

} // namespace radiant::app
