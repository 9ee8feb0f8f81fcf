#include "app/panels/InfoPanel.h"

#include <imgui.h>

#include "app/ui/FrameStats.h"
#include "app/ui/SidebarLayout.h"

namespace radiant::app {
namespace {

void row(const char* label, const char* format, auto... values) {
    ui::labelValueRow(label, 6.0f, format, values...);
}

void control(const char* input, const char* action) {
    const float start = ImGui::GetCursorPosX();
    ImGui::TextUnformatted(input);
    // The column clears the longest input name at any font size.
    ImGui::SameLine(start + ImGui::CalcTextSize("Right/middle drag").x + ImGui::GetFontSize());
    // Long actions wrap under themselves at the sidebar's edge.
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", action);
    ImGui::PopTextWrapPos();
}

} // namespace

void InfoPanel::draw() {
    const double frameMs = frames_.medianSeconds() * 1e3;
    row("Frame", "%.2f ms", frameMs);
    ImGui::SameLine();
    ImGui::TextDisabled("(median of %zu)", frames_.count());
    row("Rate", "%.0f FPS", frameMs > 0 ? 1e3 / frameMs : 0.0);
    row("Context", "OpenGL %d.%d core", gl_.major, gl_.minor);
    if (!fallbackNote_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.75f, 0.35f, 1.0f));
        ImGui::TextWrapped("%s", fallbackNote_.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::TextDisabled("Renderer");
    ImGui::TextWrapped("%s", gl_.renderer.c_str());
    ImGui::TextDisabled("Version");
    ImGui::TextWrapped("%s", gl_.version.c_str());

    ImGui::Spacing();
    ImGui::TextDisabled("Controls");
    control("Left drag", "orbit");
    control("Right/middle drag", "pan");
    control("Wheel", "zoom");
    control("Left click", "probe a point");
    control("Space", "run / pause the solve");
    control("N or Right", "one step (hold: repeat)");
    control("R", "reset the solve");
    control("K", "re-key the exposure on this solution");
    control("F", "false colour on/off");
    control("W", "patch wireframe on/off");
    control("C", "home (Cornell) view");
    control("H", "hide/show panels");
    control("S", "dome over the probe point on/off");
    control("F12", "screenshot to PNG");
    control("Esc", "quit");
}

} // namespace radiant::app
