#include "app/ui/StatusBar.h"
#include "app/ui/WrappedText.h"

#include <imgui.h>

#include <cfloat>

namespace radiant::app {
namespace {

/// Text that continues the current line when it fits there, else starts a new one; long text wraps
/// at the strip's edge (a projector's 1.5-2x scale cut the solve's state off mid-word).
void textOnThisLineIfItFits(const char* text, bool disabled, float gap) {
    ImGui::SameLine(0, gap);
    if (ImGui::CalcTextSize(text).x > ImGui::GetContentRegionAvail().x) ImGui::NewLine();
    if (disabled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ui::wrappedTextUnformatted(text);
    if (disabled) ImGui::PopStyleColor();
}

} // namespace

float drawStatusBar(const render::Viewport& view, const StatusLine& status) {
    const float pad = ImGui::GetStyle().WindowPadding.x;
    const float width = static_cast<float>(view.width);
    // Anchored at the view's bottom edge, as tall as its lines need.
    ImGui::SetNextWindowPos({static_cast<float>(view.x), static_cast<float>(view.y + view.height)}, ImGuiCond_Always,
                            {0.0f, 1.0f});
    ImGui::SetNextWindowSizeConstraints({width, 0.0f}, {width, FLT_MAX});
    ImGui::SetNextWindowBgAlpha(0.55f);
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs |
                                       ImGuiWindowFlags_AlwaysAutoResize;
    ImGui::Begin("##status", nullptr, flags);
    ImGui::AlignTextToFramePadding();
    if (!status.activity.empty()) {
        ImGui::TextUnformatted(status.activity.c_str());
        ImGui::SameLine();
        const float barWidth = ImGui::GetFontSize() * 14.0f;
        if (status.fraction >= 0)
            ImGui::ProgressBar(static_cast<float>(status.fraction), {barWidth, 0});
        else
            ImGui::ProgressBar(0.0f, {barWidth, 0}, "...");
        textOnThisLineIfItFits(status.solve.c_str(), false, pad * 2.0f);
    } else {
        ui::wrappedTextUnformatted(status.solve);
    }
    if (!status.message.empty()) textOnThisLineIfItFits(status.message.c_str(), true, pad * 2.0f);
    const float height = ImGui::GetWindowHeight();
    ImGui::End();
    return height;
}

} // namespace radiant::app
