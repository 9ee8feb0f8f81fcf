#pragma once
// A colour scale drawn across a panel: the bar in `pieces` linear steps of `colourAt(t)` (t in
// [0, 1]), a tick under it at each of the legend's ticks and the tick's number where it has room.
// The Display panel's false-colour legend and the Hemisphere panel's delta form factor scale.
#include <functional>

#include <imgui.h>

#include <glm/vec3.hpp>

#include "render/ColourScale.h"

namespace radiant::app {

struct HorizontalColourBar {
    ImVec2 lo, hi;                        ///< the bar's corners (screen)
    int pieces = 32;                      ///< linear steps: enough that the ramp looks smooth
    float labelGapInFonts = 0.3f;         ///< a label closer than this to the previous one is left out
    bool outlined = false;                ///< a border around the bar
};

/// An sRGB colour (components in [0, 1]) as ImGui's packed colour, opaque.
[[nodiscard]] inline ImU32 colourU32(const glm::dvec3& srgb) {
    return ImGui::GetColorU32(
        ImVec4(static_cast<float>(srgb.x), static_cast<float>(srgb.y), static_cast<float>(srgb.z), 1.0f));
}

/// Draws into the current window's draw list; reserves no layout room (the caller's Dummy does).
void drawHorizontalColourBar(const HorizontalColourBar& bar, const std::function<ImU32(double)>& colourAt,
                             const render::ColourLegend& ticks);

} // namespace radiant::app
