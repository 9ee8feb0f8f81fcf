#include "app/lessons/LessonCaption.h"

#include <imgui.h>

#include <algorithm>

namespace radiant::app {

/// The step's title and caption, large, in the 3D view's lower left corner: what the lecturer
/// talks about, readable from the back of the room.
void drawLessonCaption(const LessonPlayer& lessons, const render::Viewport& view) {
    if (!lessons.isOpen() || lessons.lesson().session) return;
    const lesson::LessonStep& step = lessons.lesson().steps[lessons.step()];
    const float margin = ImGui::GetFontSize();
    const float width = std::max(12 * margin, std::min(0.7f * static_cast<float>(view.width), 40 * margin));
    // `view` ends above the status bar (Lab), which grows a line when its text wraps.
    ImGui::SetNextWindowPos({static_cast<float>(view.x) + margin, static_cast<float>(view.y + view.height) - 0.5f * margin},
                            ImGuiCond_Always, {0.0f, 1.0f});
    ImGui::SetNextWindowSizeConstraints({0, 0}, {width, static_cast<float>(view.height) * 0.6f});
    // Nearly opaque: at 0.72 the comparison's split line (drawn under every window) ran through the
    // text; the picture behind stays faintly visible.
    ImGui::SetNextWindowBgAlpha(0.9f);
    ImGui::Begin("##lesson caption", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::SetWindowFontScale(1.35f);
    ImGui::PushTextWrapPos(width - margin);
    ImGui::TextUnformatted(step.title.c_str());
    ImGui::SetWindowFontScale(1.15f);
    ImGui::TextUnformatted(step.caption.c_str());
    ImGui::SetWindowFontScale(0.9f);
    ImGui::TextDisabled("%s - step %zu of %zu - Page Down: next, Page Up: back", lessons.lesson().title.c_str(),
                        lessons.step() + 1, lessons.stepCount());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

} // namespace radiant::app
