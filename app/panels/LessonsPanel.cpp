#include "app/panels/LessonsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/ui/Colours.h"
#include "app/ui/WrappedText.h"

namespace radiant::app {

namespace {

/// The shipped lessons with their titles.
std::vector<std::pair<std::string, std::string>> findShippedLessons() {
    std::vector<std::pair<std::string, std::string>> found;
    for (const std::filesystem::path& file : lesson::shippedLessonFiles()) {
        std::string title = file.stem().string();
        // Only the title here: reading the whole lesson loads its scenes, which waits until it is opened.
        std::ifstream in(file);
        const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
        if (json.is_object() && json.contains("title") && json["title"].is_string()) title = json["title"];
        found.emplace_back(file.string(), title);
    }
    return found;
}

/// A selectable row whose text wraps at the sidebar's edge (a lesson's or a step's title can be
/// longer than the sidebar is wide, more so at a projector's UI scale).
bool wrappedSelectable(const void* id, const std::string& text, bool selected) {
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 textSize = ImGui::CalcTextSize(text.c_str(), nullptr, false, width);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::PushID(id);
    const bool clicked = ImGui::Selectable("##row", selected, 0, ImVec2(width, textSize.y));
    ImGui::PopID();
    ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, ImGui::GetColorU32(ImGuiCol_Text),
                                        text.c_str(), nullptr, width);
    return clicked;
}

} // namespace

LessonsPanel::LessonsPanel(LessonPlayer& player, std::function<std::string(const std::string&)> open)
    : player_(player), open_(std::move(open)) {
    for (auto& [path, title] : findShippedLessons()) shipped_.push_back({path, title});
}

void LessonsPanel::draw() {
    if (player_.isOpen() && !player_.lesson().session) {
        drawLesson();
        ImGui::Separator();
    }
    if (shipped_.empty()) ImGui::TextDisabled("No lessons found in the assets folder.");
    for (const Shipped& lesson : shipped_) {
        const bool current = player_.isOpen() && !player_.lesson().session && player_.lesson().file == lesson.path;
        if (wrappedSelectable(&lesson, lesson.title, current)) error_ = open_(lesson.path);
    }
    ImGui::Spacing();
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Open").x - 3 * ImGui::GetStyle().FramePadding.x -
                            ImGui::GetStyle().ItemSpacing.x);
    if (focusPath_) {
        ImGui::SetKeyboardFocusHere();
        focusPath_ = false;
    }
    const bool entered = ImGui::InputTextWithHint("##lessonpath", "lesson or session file (.json)", path_.data(), path_.size(),
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || entered) && path_[0] != '\0') error_ = open_(path_.data());
    if (!error_.empty()) {
        ui::wrappedTextColoured(theme::kErrorRed, error_);
    }
}

void LessonsPanel::drawLesson() {
    const lesson::Lesson& lesson = player_.lesson();
    ui::wrappedTextUnformatted(lesson.title);
    ImGui::TextDisabled("step %zu of %zu%s", player_.step() + 1, player_.stepCount(),
                        player_.settled() ? "" : " (setting up)");
    ImGui::BeginDisabled(player_.step() == 0);
    if (ImGui::Button("< Previous")) player_.previous();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(player_.step() + 1 >= player_.stepCount());
    if (ImGui::Button("Next >")) player_.next();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Close")) {
        player_.close();
        return;
    }
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const std::string label = std::to_string(i + 1) + ". " + lesson.steps[i].title;
        if (wrappedSelectable(&lesson.steps[i], label, i == player_.step())) player_.goTo(i);
    }
}

} // namespace radiant::app
