#include "app/ui/SidebarLayout.h"

#include <cstdarg>
#include <cstdio>

namespace radiant::app::ui {

void labelValueRow(const char* label, float valueColumn, const char* format, ...) {
    char value[256];
    va_list arguments;
    va_start(arguments, format);
    std::vsnprintf(value, sizeof value, format, arguments);
    va_end(arguments);

    ImGui::TextDisabled("%s", label);
    const float column = ImGui::GetFontSize() * valueColumn;
    const float labelRight = ImGui::GetItemRectMax().x;
    const float valueLeft = ImGui::GetWindowPos().x - ImGui::GetScrollX() + column;
    if (labelRight + ImGui::GetStyle().ItemSpacing.x <= valueLeft) {
        ImGui::SameLine(column);
        ImGui::TextUnformatted(value);
        return;
    }
    const float indent = ImGui::GetFontSize();
    ImGui::Indent(indent);
    ImGui::TextUnformatted(value);
    ImGui::Unindent(indent);
}

void sameLineIfFits(float nextWidth) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + nextWidth <= right) ImGui::SameLine();
}

float radioButtonWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

void setNextWidthBesideLabel(const char* label) {
    ImGui::SetNextItemWidth(-(ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().ItemInnerSpacing.x));
}

} // namespace radiant::app::ui
