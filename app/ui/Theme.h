#pragma once
// The lab's look: a calm dark theme whose accent is reserved for what the user acts on, so the
// coloured Cornell box stays the brightest thing on a projected screen.
struct ImGuiStyle;

namespace radiant::app {

/// The panels' backdrop (sRGB-encoded, as written to the framebuffer), also behind the 3D view. The
/// lab clears the whole window to it, so the sidebar draws no background of its own: on llvmpipe,
/// blending a quad over the 375 x 1000 sidebar cost 1.5-2 ms of a ~20 ms frame.
struct BackdropColour {
    float r, g, b;
};
inline constexpr BackdropColour kBackdrop{30.0f / 255.0f, 33.0f / 255.0f, 38.0f / 255.0f};

/// Resets `style` to the theme at the given UI scale (spacing and rounding scale with the font).
void applyTheme(ImGuiStyle& style, float scale);

} // namespace radiant::app
