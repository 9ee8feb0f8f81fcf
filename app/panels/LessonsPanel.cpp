#include "app/panels/LessonsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/ui/Colours.h"

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
        if (ImGui::Selectable(lesson.title.c_str(), current)) error_ = open_(lesson.path);
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
        ImGui::PushStyleColor(ImGuiCol_Text, theme::kErrorRed);
        ImGui::TextWrapped("%s", error_.c_str());
        ImGui::PopStyleColor();
    }
}

void LessonsPanel::drawLesson() {
    const lesson::Lesson& lesson = player_.lesson();
    ImGui::TextWrapped("%s", lesson.title.c_str());
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
        if (ImGui::Selectable(label.c_str(), i == player_.step())) player_.goTo(i);
    }
}

} // namespace radiant::app
