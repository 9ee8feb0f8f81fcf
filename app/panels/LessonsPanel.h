#pragma once
// Lessons: open one of the lessons that ship in assets/lessons (or any lesson file by path), see its
// steps, and go forward and back (also Page Down / Page Up). The lab plays the steps; this panel only
// chooses them.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "app/lessons/LessonPlayer.h"
#include "app/panels/Panel.h"

namespace radiant::app {

class LessonsPanel final : public Panel {
public:
    /// `open` reads and starts a lesson file, returning why it could not (empty on success).
    LessonsPanel(LessonPlayer& player, std::function<std::string(const std::string&)> open);
    [[nodiscard]] const char* title() const override { return "Lessons"; }
    [[nodiscard]] bool openByDefault() const override { return false; }
    [[nodiscard]] bool busy() const override { return player_.isOpen() && !player_.settled(); }
    void draw() override;
    /// Puts the keyboard in the path field at the next draw (Ctrl+O).
    void focusPath() { focusPath_ = true; }

private:
    struct Shipped {
        std::string path;
        std::string title;
    };
    void drawLesson();

    LessonPlayer& player_;
    std::function<std::string(const std::string&)> open_;
    std::vector<Shipped> shipped_;
    std::array<char, 1024> path_{};
    std::string error_;
    bool focusPath_ = false;
};

} // namespace radiant::app
