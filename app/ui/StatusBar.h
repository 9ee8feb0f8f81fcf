#pragma once
// A strip along the bottom of the 3D view: what the lab is busy with (loading, meshing, form
// factors, with a progress bar), the solve's state, and the last message (a saved screenshot).
// As many lines as its text needs at the UI scale: nothing is cut off at the view's edge.
// Drawn over the view, so it shows even when every panel is collapsed.
#include <string>

#include "render/camera/Camera.h"

namespace radiant::app {

struct StatusLine {
    std::string activity;   ///< "computing form factors"; empty when nothing long is under way
    double fraction = -1;   ///< of the activity, in [0, 1]; negative when unknown
    std::string solve;      ///< "Gauss-Seidel - iteration 12 - residual 3.1e-04"
    std::string message;    ///< the last one-off message, e.g. "saved radiant-20260101-120000.png"
};

/// `view` in ImGui coordinates. Call between ImGui's NewFrame and Render. Returns the strip's
/// height (ImGui units), which other overlays at the view's bottom keep clear of.
float drawStatusBar(const render::Viewport& view, const StatusLine& status);

} // namespace radiant::app
