#pragma once
// The panels docked at the window's left edge, full height, one collapsible section each, so the
// 3D view keeps the rest of the window to itself and nothing floats over the box. Its right edge
// drags to widen it (a projector's large UI scale, a long table); the width is kept in font units,
// so changing the UI scale keeps the proportions.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/panels/Panel.h"

namespace radiant::app {

class Sidebar {
public:
    void add(std::unique_ptr<Panel> panel) { panels_.push_back(std::move(panel)); }
    /// Lets every panel poll its background work; call each frame, whether the sidebar shows or not.
    void update() {
        for (const auto& panel : panels_) panel->update();
    }
    [[nodiscard]] bool busy() const {
        for (const auto& panel : panels_)
            if (panel->busy()) return true;
        return false;
    }
    [[nodiscard]] bool refreshesUnprompted() const {
        for (const auto& panel : panels_)
            if (panel->refreshesUnprompted()) return true;
        return false;
    }
    /// Draws the sidebar; returns its width in ImGui (window) coordinates.
    float draw(const std::string& heading, const std::string& subheading);
    /// At the next draw, expands the panel titled `title` (and every section inside it) and collapses
    /// the others; empty expands all.
    void focus(std::string title) {
        focus_ = std::move(title);
        focusPending_ = true;
    }

private:
    std::vector<std::unique_ptr<Panel>> panels_;
    std::string focus_;
    bool focusPending_ = false;
    float widthInFontSizes_ = 22.0f;  ///< wide enough for a GL renderer string and a labelled slider
};

} // namespace radiant::app
