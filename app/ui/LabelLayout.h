#pragma once
// Keeps a picture's labels from covering each other (the lecture demos' readouts: the cursor's over
// the source's). GL- and ImGui-free, so it is tested without a window.
#include <vector>

namespace radiant::app::ui {

struct LabelBox {
    float x = 0, y = 0;           ///< top-left corner, UI units (y down)
    float width = 0, height = 0;
    bool pinned = false;          ///< stays where it is (a tick label: its place is its meaning)
};

/// Moves the unpinned boxes up or down, each as little as it can, so that no two boxes overlap
/// (`gap` apart at least) and each stays within [top, bottom] where it fits. Pinned boxes keep their
/// place, then the others are placed in order: an earlier box keeps its place before a later one.
/// A box that fits nowhere free stays where it was asked to be.
void separateLabels(std::vector<LabelBox>& boxes, float top, float bottom, float gap);

} // namespace radiant::app::ui
