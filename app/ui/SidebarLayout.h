#pragma once
// Layout helpers that keep the panels' text inside the sidebar at any UI scale or sidebar width:
// "label  value" rows, a unit or radio button that follows only when it fits, a widget sized to
// leave its label room. tests/gl/test_sidebar_layout.cpp checks the result.
#include <imgui.h>

namespace radiant::app::ui {

/// A dim label, then the value from `valueColumn` font sizes into the content region, like a table
/// column; a label longer than that puts its value on the next line, indented, rather than running
/// into it ("Unshot power0.1578 W").
void labelValueRow(const char* label, float valueColumn, const char* format, ...) IM_FMTARGS(3);

/// SameLine() when an item `nextWidth` wide still fits on this line, else nothing (the next item
/// starts a new line): for a unit after a value.
void sameLineIfFits(float nextWidth);

/// The width of ImGui::RadioButton(label), for sameLineIfFits.
[[nodiscard]] float radioButtonWidth(const char* label);

/// Sizes the next widget to fill the line less its label (visible part, before any "##").
void setNextWidthBesideLabel(const char* label);

} // namespace radiant::app::ui
