#include "app/panels/InfoPanel.h"

#include <imgui.h>

#include "app/ui/FrameStats.h"
#include "app/ui/Shortcuts.h"
#include "app/ui/SidebarLayout.h"
#include "app/ui/WrappedText.h"

namespace radiant::app {
namespace {

void infoRow(const char* label, const char* format, auto... values) {
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
    infoRow("Frame", "%.2f ms", frameMs);
    ImGui::SameLine();
    ImGui::TextDisabled("(median of %zu)", frames_.count());
    infoRow("Rate", "%.0f FPS", frameMs > 0 ? 1e3 / frameMs : 0.0);
    infoRow("Context", "OpenGL %d.%d core", gl_.major, gl_.minor);
    if (!fallbackNote_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.75f, 0.35f, 1.0f));
        ui::wrappedTextUnformatted(fallbackNote_);
        ImGui::PopStyleColor();
    }
    ImGui::TextDisabled("Renderer");
    ui::wrappedTextUnformatted(gl_.renderer);
    ImGui::TextDisabled("Version");
    ui::wrappedTextUnformatted(gl_.version);

    ImGui::Spacing();
    ImGui::TextDisabled("Controls");
    for (const MouseControl& mouse : labMouseControls()) control(mouse.input, mouse.does);
    for (const Shortcut& shortcut : labShortcuts()) control(shortcut.keys, shortcut.does);
}

} // namespace radiant::app
