#include "app/ui/Sidebar.h"

#include <imgui.h>

namespace radiant::app {

float Sidebar::draw(const std::string& heading, const std::string& subheading) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    // Wide enough for a GL renderer string and a labelled slider at any UI scale.
    const float width = ImGui::GetFontSize() * 22.0f;
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize({width, viewport->WorkSize.y});
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
    // The window's clear has painted the backdrop (app/ui/Theme.h): no second, blended coat.
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
    ImGui::Begin("##sidebar", nullptr, flags);
    ImGui::PopStyleColor();
    // Where the panels end and the 3D view, on the same backdrop, begins (behind the window: its own
    // draw list clips to inside the scrollbar).
    const ImVec2 origin = ImGui::GetWindowPos();
    ImGui::GetBackgroundDrawList()->AddLine({origin.x + width - 0.5f, origin.y},
                                        {origin.x + width - 0.5f, origin.y + viewport->WorkSize.y},
                                        ImGui::GetColorU32(ImGuiCol_Border));
    ImGui::TextUnformatted(heading.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", subheading.c_str());
    ImGui::Separator();
    ImGui::Spacing();
    for (const auto& panel : panels_) {
        const ImGuiTreeNodeFlags headerFlags = panel->openByDefault() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
        if (focusPending_) ImGui::SetNextItemOpen(focus_.empty() || focus_ == panel->title());
        if (ImGui::CollapsingHeader(panel->title(), headerFlags)) {
            ImGui::PushID(panel.get());
            ImGui::Indent(ImGui::GetStyle().IndentSpacing * 0.25f);
            panel->draw();
            ImGui::Unindent(ImGui::GetStyle().IndentSpacing * 0.25f);
            ImGui::PopID();
            ImGui::Spacing();
        }
    }
    focusPending_ = false;
    ImGui::End();
    return width;
}

} // namespace radiant::app
