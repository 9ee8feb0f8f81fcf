#include "app/ui/HorizontalColourBar.h"

#include <string>

namespace radiant::app {

void drawHorizontalColourBar(const HorizontalColourBar& bar, const std::function<ImU32(double)>& colourAt,
                             const render::ColourLegend& ticks) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float font = ImGui::GetFontSize();
    const float width = bar.hi.x - bar.lo.x;
    for (int i = 0; i < bar.pieces; ++i) {
        const double t0 = i / static_cast<double>(bar.pieces), t1 = (i + 1) / static_cast<double>(bar.pieces);
        const float x0 = bar.lo.x + width * static_cast<float>(t0), x1 = bar.lo.x + width * static_cast<float>(t1);
        const ImU32 left = colourAt(t0), right = colourAt(t1);
        draw->AddRectFilledMultiColor(ImVec2(x0, bar.lo.y), ImVec2(x1 + 0.5f, bar.hi.y), left, right, right, left);
    }
    if (bar.outlined) draw->AddRect(bar.lo, bar.hi, ImGui::GetColorU32(ImGuiCol_Border));

    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    float lastLabelEnd = -1e9f;
    for (const double tick : ticks.ticksW_m2) {
        const float x = bar.lo.x + width * static_cast<float>(ticks.position(tick));
        draw->AddLine(ImVec2(x, bar.hi.y), ImVec2(x, bar.hi.y + font * 0.3f), text);
        const std::string label = render::formatLegendTick(tick);
        const float labelWidth = ImGui::CalcTextSize(label.c_str()).x;
        const float left = x - labelWidth / 2;
        if (left < lastLabelEnd + font * bar.labelGapInFonts) continue;  // crowded: keep the tick, drop its number
        draw->AddText(ImVec2(left, bar.hi.y + font * 0.35f), text, label.c_str());
        lastLabelEnd = left + labelWidth;
    }
}

} // namespace radiant::app
