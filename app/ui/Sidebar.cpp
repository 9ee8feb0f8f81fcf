#include "app/ui/Sidebar.h"

#include <imgui.h>

#include <algorithm>

namespace radiant::app {

float Sidebar::draw(const std::string& heading, const std::string& subheading) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float fontSize = ImGui::GetFontSize();
    // The 3D view keeps at least 40% of the window; the sidebar keeps room for a slider and its label.
    const float narrowest = std::min(fontSize * 14.0f, viewport->WorkSize.x * 0.6f);
    const float widest = std::max(narrowest, viewport->WorkSize.x * 0.6f);
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize({std::clamp(widthInFontSizes_ * fontSize, narrowest, widest), viewport->WorkSize.y});
    // Only the width follows a drag: the height is the window's, and the left edge stays put.
    ImGui::SetNextWindowSizeConstraints({narrowest, viewport->WorkSize.y}, {widest, viewport->WorkSize.y});
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                       ImGuiWindowFlags_NoSavedSettings;
    // The window's clear has painted the backdrop (app/ui/Theme.h): no second, blended coat.
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
    ImGui::Begin("##sidebar", nullptr, flags);
    ImGui::PopStyleColor();
    // This frame's size already includes a drag of its edge (ImGui applies it inside Begin).
    const float width = ImGui::GetWindowWidth();
    widthInFontSizes_ = width / fontSize;
    // Where the panels end and the 3D view, on the same backdrop, begins (behind the window: its own
    // draw list clips to inside the scrollbar).
    const ImVec2 origin = ImGui::GetWindowPos();
    ImGui::GetBackgroundDrawList()->AddLine({origin.x + width - 0.5f, origin.y},
                                        {origin.x + width - 0.5f, origin.y + viewport->WorkSize.y},
                                        ImGui::GetColorU32(ImGuiCol_Border));
    // Widgets without a width of their own leave room for their label at the right (ImGui's default,
    // two thirds of the window, ignores indentation and cut "power P (W)" to "power P (V").
    ImGui::PushItemWidth(-fontSize * 9.0f);
    // Prose wraps at the sidebar's edge (or its table column's) instead of running past it; numbers
    // and labels that must stay whole are laid out to fit (app/ui/SidebarLayout.h).
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(heading.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", subheading.c_str());
    ImGui::Separator();
    ImGui::Spacing();
    for (const auto& panel : panels_) {
        const ImGuiTreeNodeFlags headerFlags = panel->openByDefault() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
        if (focusPending_) {
            const bool open = focus_.empty() || focus_ == panel->title();
            ImGui::SetNextItemOpen(open);
            if (open) panel->expandAll();
        }
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
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
    ImGui::End();
    return width;
}

} // namespace radiant::app
