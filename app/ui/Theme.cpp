#include "app/ui/Theme.h"

#include <imgui.h>

namespace radiant::app {
namespace {
ImVec4 rgb(int r, int g, int b, float a = 1.0f) {
    return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f, a};
}
} // namespace

void applyTheme(ImGuiStyle& style, float scale) {
    style = ImGuiStyle();
    ImGui::StyleColorsDark(&style);

    style.WindowPadding = {14, 12};
    style.FramePadding = {8, 5};
    style.ItemSpacing = {8, 7};
    style.ItemInnerSpacing = {6, 5};
    style.IndentSpacing = 16;
    style.ScrollbarSize = 12;
    style.GrabMinSize = 10;
    style.WindowBorderSize = 0;
    style.FrameBorderSize = 0;
    style.PopupBorderSize = 1;
    style.WindowRounding = 0;  // docked panels meet the window edge
    style.FrameRounding = 4;
    style.GrabRounding = 4;
    style.PopupRounding = 4;
    style.ScrollbarRounding = 6;
    style.TabRounding = 4;
    style.WindowTitleAlign = {0.0f, 0.5f};

    const ImVec4 background = rgb(24, 26, 30);
    const ImVec4 panel{kBackdrop.r, kBackdrop.g, kBackdrop.b, 1.0f};
    const ImVec4 frame = rgb(43, 47, 54);
    const ImVec4 frameHover = rgb(54, 59, 68);
    const ImVec4 accent = rgb(79, 140, 214);
    const ImVec4 accentHover = rgb(98, 158, 230);
    const ImVec4 text = rgb(222, 225, 230);
    const ImVec4 textDim = rgb(140, 146, 156);

    ImVec4* c = style.Colors;
    c[ImGuiCol_Text] = text;
    c[ImGuiCol_TextDisabled] = textDim;
    c[ImGuiCol_WindowBg] = panel;
    c[ImGuiCol_ChildBg] = panel;
    c[ImGuiCol_PopupBg] = rgb(36, 39, 45, 0.98f);
    c[ImGuiCol_Border] = rgb(58, 63, 72);
    c[ImGuiCol_BorderShadow] = rgb(0, 0, 0, 0);
    c[ImGuiCol_FrameBg] = frame;
    c[ImGuiCol_FrameBgHovered] = frameHover;
    c[ImGuiCol_FrameBgActive] = rgb(62, 68, 79);
    c[ImGuiCol_TitleBg] = background;
    c[ImGuiCol_TitleBgActive] = background;
    c[ImGuiCol_TitleBgCollapsed] = background;
    c[ImGuiCol_MenuBarBg] = background;
    c[ImGuiCol_ScrollbarBg] = rgb(0, 0, 0, 0);
    c[ImGuiCol_ScrollbarGrab] = frameHover;
    c[ImGuiCol_ScrollbarGrabHovered] = rgb(72, 78, 90);
    c[ImGuiCol_ScrollbarGrabActive] = accent;
    c[ImGuiCol_CheckMark] = accentHover;
    c[ImGuiCol_SliderGrab] = accent;
    c[ImGuiCol_SliderGrabActive] = accentHover;
    c[ImGuiCol_Button] = frame;
    c[ImGuiCol_ButtonHovered] = frameHover;
    c[ImGuiCol_ButtonActive] = accent;
    c[ImGuiCol_Header] = rgb(40, 44, 51);
    c[ImGuiCol_HeaderHovered] = frameHover;
    c[ImGuiCol_HeaderActive] = rgb(62, 68, 79);
    c[ImGuiCol_Separator] = rgb(50, 54, 62);
    c[ImGuiCol_SeparatorHovered] = accent;
    c[ImGuiCol_SeparatorActive] = accentHover;
    c[ImGuiCol_ResizeGrip] = rgb(0, 0, 0, 0);
    c[ImGuiCol_ResizeGripHovered] = accent;
    c[ImGuiCol_ResizeGripActive] = accentHover;
    c[ImGuiCol_Tab] = frame;
    c[ImGuiCol_TabHovered] = accent;
    c[ImGuiCol_TabActive] = rgb(58, 98, 150);
    c[ImGuiCol_PlotHistogram] = accent;
    c[ImGuiCol_PlotHistogramHovered] = accentHover;
    c[ImGuiCol_TextSelectedBg] = rgb(79, 140, 214, 0.35f);
    c[ImGuiCol_NavHighlight] = accent;

    style.ScaleAllSizes(scale);
}

} // namespace radiant::app
