#pragma once
// The lab's look: a calm dark theme whose accent is reserved for what the user acts on, so the
// coloured Cornell box stays the brightest thing on a projected screen.
struct ImGuiStyle;

namespace radiant::app {

/// Resets `style` to the theme at the given UI scale (spacing and rounding scale with the font).
void applyTheme(ImGuiStyle& style, float scale);

} // namespace radiant::app
