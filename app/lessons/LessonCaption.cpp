#include "app/lessons/LessonCaption.h"

#include <imgui.h>

#include <algorithm>

namespace radiant::app {

/// The step's title and caption, large, across the 3D view's bottom: what the lecturer talks about,
/// readable from the back of the room. The picture is drawn above it, never under it: over the
/// picture (as it was until 2026-12-03) the caption hid the Cornell box's floor, the probe marker
/// on it and the lecture demos' figures and labels at UI scale 1.5.
float drawLessonCaption(const LessonPlayer& lessons, const render::Viewport& view) {
    if (!lessons.isOpen() || lessons.lesson().session) return 0.0f;
    const lesson::LessonStep& step = lessons.lesson().steps[lessons.step()];
    const float margin = ImGui::GetFontSize();
    const float gap = 0.5f * margin;
    // The whole view's width: fewer lines than a narrower box, so a lower band.
    const float width = std::max(12 * margin, static_cast<float>(view.width) - 2 * margin);
    // `view` ends above the status bar (Lab), which grows a line when its text wraps.
    ImGui::SetNextWindowPos({static_cast<float>(view.x) + margin, static_cast<float>(view.y + view.height) - gap},
                            ImGuiCond_Always, {0.0f, 1.0f});
    // At most half the view: a long caption in a small window leaves the picture room.
    ImGui::SetNextWindowSizeConstraints({width, 0}, {width, static_cast<float>(view.height) * 0.5f});
    ImGui::SetNextWindowBgAlpha(0.9f);
    ImGui::Begin("##lesson caption", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::SetWindowFontScale(1.35f);
    ImGui::PushTextWrapPos(width - ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted(step.title.c_str());
    ImGui::SetWindowFontScale(1.15f);
    ImGui::TextUnformatted(step.caption.c_str());
    ImGui::SetWindowFontScale(0.9f);
    ImGui::TextDisabled("%s - step %zu of %zu - Page Down: next, Page Up: back", lessons.lesson().title.c_str(),
                        lessons.step() + 1, lessons.stepCount());
    ImGui::PopTextWrapPos();
    const float height = ImGui::GetWindowHeight();
    ImGui::End();
    return height + 2 * gap;  // a gap below it and one above, between it and the picture
}

} // namespace radiant::app
