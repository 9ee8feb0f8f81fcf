#include "app/ui/StatusBar.h"

#include <imgui.h>

namespace radiant::app {

void drawStatusBar(const render::Viewport& view, const StatusLine& status) {
    const float pad = ImGui::GetStyle().WindowPadding.x;
    const float lineHeight = ImGui::GetFrameHeightWithSpacing();
    const float height = lineHeight + 2.0f * ImGui::GetStyle().WindowPadding.y;
    ImGui::SetNextWindowPos({static_cast<float>(view.x), static_cast<float>(view.y + view.height) - height});
    ImGui::SetNextWindowSize({static_cast<float>(view.width), height});
    ImGui::SetNextWindowBgAlpha(0.55f);
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
    ImGui::Begin("##status", nullptr, flags);
    if (!status.activity.empty()) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(status.activity.c_str());
        ImGui::SameLine();
        const float barWidth = ImGui::GetFontSize() * 14.0f;
        if (status.fraction >= 0)
            ImGui::ProgressBar(static_cast<float>(status.fraction), {barWidth, 0});
        else
            ImGui::ProgressBar(0.0f, {barWidth, 0}, "...");
        ImGui::SameLine(0, pad * 2.0f);
    } else {
        ImGui::AlignTextToFramePadding();
    }
    ImGui::TextUnformatted(status.solve.c_str());
    if (!status.message.empty()) {
        ImGui::SameLine(0, pad * 2.0f);
        ImGui::TextDisabled("%s", status.message.c_str());
    }
    ImGui::End();
}

} // namespace radiant::app
