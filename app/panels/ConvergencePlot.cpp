#include "app/panels/ConvergencePlot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "app/solver/Comparison.h"
#include "app/solver/ConvergenceCsv.h"
#include "app/solver/ConvergenceQuantity.h"
#include "app/ui/Colours.h"
#include "app/ui/ComparisonColours.h"
#include "app/ui/PlotAxes.h"
#include "app/ui/WrappedText.h"

namespace radiant::app {
namespace {

const ImU32 kPlotBackground = IM_COL32(40, 44, 52, 255);
const ImU32 kGrid = IM_COL32(70, 74, 86, 255);
const ImU32 kTickText = IM_COL32(170, 170, 180, 255);
const ImU32 kTolerance = IM_COL32(235, 235, 235, 200);

/// One colour per method, in the table's order (Okabe & Ito's palette: told apart with any colour
/// vision, and on a projector).
ImU32 methodColour(SolverMethod method) {
    static constexpr ImU32 kColours[] = {IM_COL32(230, 159, 0, 255), IM_COL32(86, 180, 233, 255),
                                         IM_COL32(0, 158, 115, 255), IM_COL32(204, 121, 167, 255),
                                         IM_COL32(240, 228, 66, 255)};
    const auto methods = solverMethods();
    for (std::size_t i = 0; i < methods.size(); ++i)
        if (methods[i].method == method) return kColours[i % std::size(kColours)];
    return kTickText;
}

/// A polyline drawn in dashes of `dash` pixels (gaps as long), the pattern running on across points.
void dashedPolyline(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 colour, float thickness, float dash) {
    float phase = 0;  // distance along the current dash or gap
    bool on = true;
    for (std::size_t i = 1; i < points.size(); ++i) {
        ImVec2 a = points[i - 1];
        const ImVec2 b = points[i];
        float remaining = std::hypot(b.x - a.x, b.y - a.y);
        if (remaining <= 0) continue;
        const ImVec2 unit{(b.x - a.x) / remaining, (b.y - a.y) / remaining};
        while (remaining > 0) {
            const float piece = std::min(remaining, dash - phase);
            const ImVec2 end{a.x + unit.x * piece, a.y + unit.y * piece};
            if (on) draw->AddLine(a, end, colour, thickness);
            a = end;
            remaining -= piece;
            phase += piece;
            if (phase >= dash) {
                phase = 0;
                on = !on;
            }
        }
    }
}

std::string exponentLabel(int exponent) {
    char text[16];
    std::snprintf(text, sizeof text, "1e%d", exponent);
    return text;
}

} // namespace

ConvergencePlot::ConvergencePlot() {
    const char* name = "convergence.csv";
    std::copy(name, name + std::char_traits<char>::length(name), csvPath_.begin());
}

std::vector<ConvergencePlot::Curve> ConvergencePlot::curves(const Snapshot& snapshot, const Snapshot* second) {
    std::vector<Curve> curves;
    if (second) {
        // Comparison mode: the run of each side, in its side's colour (both may be one method).
        const auto add = [&](const Snapshot& s, char side, ImU32 colour, double patchAreaScale) {
            if (s.history.empty()) return;
            curves.push_back({&s.history, s.method, comparisonLabel(side, s.method, patchAreaScale), colour, false});
        };
        add(snapshot, 'A', theme::kSideA, 1.0);
        add(*second, 'B', theme::kSideB, second->meshing.maxPatchArea / std::max(snapshot.meshing.maxPatchArea, 1e-300));
        return curves;
    }
    std::vector<SegmentView> segments = snapshot.convergence.segments(snapshot.history);
    if (segments.size() > kMaxSegmentsShown)
        segments.erase(segments.begin(), segments.end() - static_cast<std::ptrdiff_t>(kMaxSegmentsShown));
    for (const SegmentView& segment : segments)
        curves.push_back({segment.steps, segment.info->method, segment.info->label, methodColour(segment.info->method),
                          segment.info->index != 0});
    return curves;
}

void ConvergencePlot::draw(const Snapshot& snapshot, const Snapshot* second) {
    const std::vector<Curve> segments = curves(snapshot, second);
    if (segments.empty()) {
        ImGui::TextDisabled("Convergence: no steps yet (Run or Step)");
        return;
    }

    const float font = ImGui::GetFontSize();
    const float width = ImGui::GetContentRegionAvail().x;
    const float height = font * 11.0f;
    const float left = ImGui::CalcTextSize("1e-10").x + font * 0.4f;
    const float bottom = font * 1.3f;
    const float right = font * 0.6f;  // room for the last x label's right half

    // What the y axis shows: the quantities of the curves on it, all fractions of emitted power.
    std::set<std::string_view> quantities;
    std::size_t longest = 1;
    // Half the tolerance: its line stays clear of the bottom edge, where its label would sit on the ticks.
    std::vector<double> values{snapshot.tolerance, 0.5 * snapshot.tolerance};
    const auto plotWidthPixels = static_cast<std::size_t>(std::max(1.0f, width - left - right));
    for (const Curve& segment : segments) {
        quantities.insert(convergenceQuantity(segment.method).name);
        longest = std::max(longest, segment.steps->size());
    }
    // Long runs (thousands of shots) are thinned to about two points per pixel.
    const std::size_t stride = std::max<std::size_t>(1, longest / (2 * plotWidthPixels));
    for (const Curve& segment : segments)
        for (std::size_t i = 0; i < segment.steps->size(); i += stride) values.push_back((*segment.steps)[i].residual);

    std::string quantity;
    for (const std::string_view q : quantities) quantity += (quantity.empty() ? "" : " / ") + std::string(q);
    ImGui::Spacing();
    ui::wrappedText("%s (fraction of emitted power), log scale, against iteration", quantity.c_str());

    const int maxYTicks = std::max(2, static_cast<int>((height - bottom) / (font * 1.4f)));
    const ui::LogAxis yAxis = ui::logAxisFor(values, maxYTicks, 2);
    const double xLow = 1, xHigh = std::max<double>(2, static_cast<double>(longest));
    const int maxXTicks = std::max(2, static_cast<int>((width - left) / (ImGui::CalcTextSize("00000").x + font)));
    const std::vector<double> xTicks = ui::linearTicks(xLow, xHigh, maxXTicks, 1.0);

    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 lo{origin.x + left, origin.y + height - bottom};  // bottom-left of the plot area
    const ImVec2 hi{origin.x + width - right, origin.y + font * 0.5f};  // top-right
    const auto toScreen = [&](double iteration, double value) {
        const double u = (iteration - xLow) / (xHigh - xLow);
        const double logValue = std::log10(std::max(value, 1e-300));
        const double v = (logValue - yAxis.lowExponent) / (yAxis.highExponent - yAxis.lowExponent);
        return ImVec2{lo.x + static_cast<float>(std::clamp(u, 0.0, 1.0)) * (hi.x - lo.x),
                      lo.y - static_cast<float>(std::clamp(v, 0.0, 1.0)) * (lo.y - hi.y)};
    };
    draw->AddRectFilled({lo.x, hi.y}, {hi.x, lo.y}, kPlotBackground);
    for (const int e : yAxis.tickExponents) {
        const ImVec2 p = toScreen(xLow, std::pow(10.0, e));
        draw->AddLine({lo.x, p.y}, {hi.x, p.y}, kGrid);
        const std::string label = exponentLabel(e);
        const ImVec2 size = ImGui::CalcTextSize(label.c_str());
        draw->AddText({lo.x - size.x - font * 0.2f, p.y - size.y * 0.5f}, kTickText, label.c_str());
    }
    for (const double x : xTicks) {
        const ImVec2 p = toScreen(x, 1.0);
        draw->AddLine({p.x, lo.y}, {p.x, hi.y}, kGrid);
        char label[24];
        std::snprintf(label, sizeof label, "%.0f", x);
        const ImVec2 size = ImGui::CalcTextSize(label);
        draw->AddText({p.x - size.x * 0.5f, lo.y + font * 0.15f}, kTickText, label);
    }
    // The tolerance: Run stops where a curve crosses it.
    {
        const ImVec2 p = toScreen(xLow, snapshot.tolerance);
        dashedPolyline(draw, {{lo.x, p.y}, {hi.x, p.y}}, kTolerance, 1.5f, font * 0.3f);
        char label[32];
        std::snprintf(label, sizeof label, "tolerance %.0e", snapshot.tolerance);
        const ImVec2 size = ImGui::CalcTextSize(label);
        // At the left, where the curves are still high above it (they start near 1 and fall).
        const float y = p.y - size.y - 1.0f < hi.y ? p.y + 1.0f : p.y - size.y - 1.0f;
        draw->AddText({lo.x + font * 0.3f, y}, kTolerance, label);
    }
    draw->PushClipRect({lo.x, hi.y}, {hi.x, lo.y}, true);
    std::vector<ImVec2> points;
    for (const Curve& segment : segments) {
        points.clear();
        const SolveHistory& steps = *segment.steps;
        for (std::size_t i = 0; i < steps.size(); i += stride)
            points.push_back(toScreen(static_cast<double>(i + 1), steps[i].residual));
        if (points.back().x != toScreen(static_cast<double>(steps.size()), steps.back().residual).x)
            points.push_back(toScreen(static_cast<double>(steps.size()), steps.back().residual));
        const ImU32 colour = segment.colour;
        if (!segment.dashed) {
            draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_None, 2.0f);
        } else {
            dashedPolyline(draw, points, colour, 2.0f, font * 0.45f);
        }
        if (points.size() <= 60)  // a dot per step while they can be told apart
            for (const ImVec2& p : points) draw->AddCircleFilled(p, 2.5f, colour);
    }
    draw->PopClipRect();
    ImGui::Dummy({width, height});
    ImGui::TextDisabled("iteration (from the start, or from the material edit)");

    // The legend: a sample of each curve's line and what it reached.
    for (const Curve& segment : segments) {
        const ImU32 colour = segment.colour;
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float swatch = font * 1.6f;
        const float y = at.y + ImGui::GetTextLineHeight() * 0.5f;
        if (!segment.dashed)
            ImGui::GetWindowDrawList()->AddLine({at.x, y}, {at.x + swatch, y}, colour, 3.0f);
        else
            dashedPolyline(ImGui::GetWindowDrawList(), {{at.x, y}, {at.x + swatch, y}}, colour, 3.0f, font * 0.35f);
        ImGui::Dummy({swatch, ImGui::GetTextLineHeight()});
        ImGui::SameLine();
        const SolveHistory& steps = *segment.steps;
        char reached[96];
        if (const std::optional<std::size_t> below = firstStepBelow(steps, snapshot.tolerance))
            std::snprintf(reached, sizeof reached, "below %.0e at iteration %zu", snapshot.tolerance, *below);
        else
            std::snprintf(reached, sizeof reached, "%.2e after %zu", steps.back().residual, steps.size());
        ui::wrappedText("%s: %s", segment.label.c_str(), reached);
    }
    drawExport(snapshot);
}

void ConvergencePlot::drawExport(const Snapshot& snapshot) {
    ImGui::Spacing();
    const char* button = "Export CSV";
    const float buttonWidth = ImGui::CalcTextSize(button).x + ImGui::GetStyle().FramePadding.x * 2.0f;
    ImGui::SetNextItemWidth(-(buttonWidth + ImGui::GetStyle().ItemSpacing.x));
    ImGui::InputText("##csvPath", csvPath_.data(), csvPath_.size());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("File for the CSV (method, segment, label, iteration, solver_iteration, quantity, value),\n"
                          "relative to the folder the lab was started in");
    ImGui::SameLine();
    if (ImGui::Button(button)) {
        const std::string path(csvPath_.data());
        try {
            const std::string csv = convergenceCsv(snapshot.convergence, snapshot.history);
            writeTextFile(path, csv);
            std::error_code ec;
            const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
            const auto rows = static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')) - 1;
            exportMessage_ = "wrote " + std::to_string(rows) + " rows to " + (ec ? path : absolute.string());
            exportFailed_ = false;
        } catch (const std::exception& e) {
            exportMessage_ = e.what();
            exportFailed_ = true;
        }
    }
    if (!exportMessage_.empty()) {
        ui::wrappedTextColoured(exportFailed_ ? theme::kErrorRed : theme::kDoneGreen, exportMessage_);
    }
}

} // namespace radiant::app
