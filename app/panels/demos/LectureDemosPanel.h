#pragma once
// The six lecture demos under one sidebar header, each in its own collapsible section, so the
// sidebar stays short on a projector. Opening a demo's section shows that demo in the 3D view
// (DemoView) and closes the other sections; closing it, or "Back to the scene", gives the 3D view
// back to the scene.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "app/panels/Panel.h"
#include "app/panels/demos/LectureDemo.h"

namespace radiant::app {

class DemoView;

class LectureDemosPanel final : public Panel {
public:
    explicit LectureDemosPanel(DemoView& view);
    [[nodiscard]] const char* title() const override { return "Lecture demos"; }
    [[nodiscard]] bool openByDefault() const override { return false; }
    void update() override { drawn_ = false; }
    void draw() override;
    /// Opens one demo's section (by its title) and shows it in the 3D view; nothing for an unknown title.
    void focus(const char* demoTitle);
    /// The same by position, in the order lesson::demoIds() names them (point source first).
    void focus(std::size_t demoIndex) {
        if (demoIndex < demos_.size()) focus(demos_[demoIndex]->title());
    }
    /// Closes the demo shown (and its section): the 3D view shows the scene again.
    void closeDemo();
    /// Whether draw() ran since the last update(): the lab closes the demo when the panel's header
    /// is folded away while the sidebar shows.
    [[nodiscard]] bool drawn() const { return drawn_; }
    void expandAll() override { expandAll_ = true; }
    [[nodiscard]] std::size_t size() const { return demos_.size(); }
    [[nodiscard]] LectureDemo& demo(std::size_t index) { return *demos_[index]; }

private:
    DemoView& view_;
    std::vector<std::unique_ptr<LectureDemo>> demos_;
    std::string focused_;      ///< the section to open at the next draw (the others close)
    bool focusPending_ = false;
    bool expandAll_ = false;
    bool drawn_ = false;
};

} // namespace radiant::app
