#pragma once
// Finds text that the last ImGui frame cut off: a window whose content runs past its right edge (the
// sidebar has no horizontal scrollbar, so whatever passes it is clipped) and a table column whose
// content, or header, runs past the column. ImGui records both extents while laying items out, so
// every Text, slider label and table cell is covered without the panels reporting anything; the
// layout test (tests/gl/test_sidebar_layout.cpp) fails on any of them at every UI scale.
// A label running into a value on the same line is neither: ui::labelValueRow (app/ui/SidebarLayout.h)
// prevents it by construction.
#include <string>
#include <vector>

namespace radiant::app::ui {

struct ClippedText {
    std::string where;   ///< the window, and the table column when in one
    float pixels = 0;    ///< how far the content passes the edge, in ImGui units
};

/// Call after the frame is rendered (ImGui::Render), on the UI thread; empty when everything fits.
std::vector<ClippedText> findClippedText();

} // namespace radiant::app::ui
