#pragma once
// The six lecture demos under one sidebar header, each in its own collapsible section, so the
// sidebar stays short on a projector.
#include <cstddef>
#include <memory>
#include <vector>

#include "app/panels/Panel.h"

namespace radiant::app {

class LectureDemosPanel final : public Panel {
public:
    LectureDemosPanel();
    [[nodiscard]] const char* title() const override { return "Lecture demos"; }
    [[nodiscard]] bool openByDefault() const override { return false; }
    void draw() override;
    /// Opens one demo's section (by its title) and closes the others; for screenshots.
    void focus(const char* demoTitle);
    /// The same by position, in the order lesson::demoIds() names them (point source first).
    void focus(std::size_t demoIndex) {
        if (demoIndex < demos_.size()) focus(demos_[demoIndex]->title());
    }
    void expandAll() override { expandAll_ = true; }

private:
    std::vector<std::unique_ptr<Panel>> demos_;
    const char* focused_ = nullptr;
    bool expandAll_ = false;
};

} // namespace radiant::app
