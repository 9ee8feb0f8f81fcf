#include "app/ui/LegendOverlay.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "app/ui/HorizontalColourBar.h"
#include "app/ui/LegendUnit.h"

namespace radiant::app {

LegendBarRect drawLegendOverlay(const render::ColourLegend& legend, const render::Viewport& view) {
    const float font = ImGui::GetFontSize();
    const float margin = font;
    ImGui::SetNextWindowPos({static_cast<float>(view.x + view.width) - margin, static_cast<float>(view.y) + margin},
                            ImGuiCond_Always, {1.0f, 0.0f});
    ImGui::SetNextWindowBgAlpha(0.72f);
    ImGui::Begin("##false colour legend", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    // "W/m²" with the UI font's superscript two; the quantity on its own line keeps the window narrow.
    ImGui::TextUnformatted(legend.quantity);
    ImGui::TextDisabled("%s%s", legendUnitForScreen(legend), legend.logScale ? ", log scale" : "");

    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float barWidth = font * 1.1f;
    // Tall enough to part 1-2-5 labels over three decades, short enough to leave the picture the view.
    const float barHeight = std::clamp(0.4f * static_cast<float>(view.height), font * 6.0f, font * 16.0f);
    const ImVec2 barLo(origin.x, origin.y + font * 0.5f);
    const ImVec2 barHi(barLo.x + barWidth, barLo.y + barHeight);
    constexpr int kPieces = 32;  // viridis is smooth enough that 32 linear pieces are exact to the eye
    for (int i = 0; i < kPieces; ++i) {
        const double t0 = i / static_cast<double>(kPieces), t1 = (i + 1) / static_cast<double>(kPieces);
        const float y0 = barHi.y - barHeight * static_cast<float>(t0), y1 = barHi.y - barHeight * static_cast<float>(t1);
        const ImU32 lower = colourU32(render::viridis(t0)), upper = colourU32(render::viridis(t1));
        draw->AddRectFilledMultiColor(ImVec2(barLo.x, y1 - 0.5f), ImVec2(barHi.x, y0), upper, upper, lower, lower);
    }
    draw->AddRect(barLo, barHi, ImGui::GetColorU32(ImGuiCol_Border));

    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    float widest = 0, lastLabelTop = 1e9f;
    // From the bottom up: where labels crowd, the tick stays and its number goes.
    for (const double tick : legend.ticksW_m2) {
        const float y = barHi.y - barHeight * static_cast<float>(legend.position(tick));
        draw->AddLine(ImVec2(barHi.x, y), ImVec2(barHi.x + font * 0.4f, y), text, std::max(1.0f, font / 14.0f));
        const std::string label = render::formatLegendTick(tick);
        const ImVec2 size = ImGui::CalcTextSize(label.c_str());
        const float top = y - size.y / 2;
        if (top + size.y > lastLabelTop) continue;
        draw->AddText(ImVec2(barHi.x + font * 0.6f, top), text, label.c_str());
        lastLabelTop = top;
        widest = std::max(widest, size.x);
    }
    ImGui::Dummy(ImVec2(barWidth + font * 0.6f + widest, barHeight + font));
    ImGui::End();
    return {barLo.x, barLo.y, barHi.x, barHi.y};
}

} // namespace radiant::app
