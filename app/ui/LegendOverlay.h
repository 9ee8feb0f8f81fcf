#pragma once
// The false-colour legend where people look: in the 3D view's top-right corner, over the picture,
// sized by the UI scale (a projector's 1.5-2 makes it readable from the back of the room). A vertical
// viridis bar, maximum at the top, a tick and label at each of the legend's ticks, the quantity and
// its unit as the title. The Display panel keeps its small copy for the settings beside it.
#include "render/ColourScale.h"
#include "render/camera/Camera.h"

namespace radiant::app {

/// Where the overlay's colour bar was drawn last, in UI units (tests look for its colours there).
struct LegendBarRect {
    float left = 0, top = 0, right = 0, bottom = 0;
};

/// Draws the legend as an ImGui window anchored to `view` (UI units); call between newFrame and render.
/// The legend's quantity and unit title it (radiosity in W/m^2, illuminance in lx, or the comparison's
/// difference ratio).
LegendBarRect drawLegendOverlay(const render::ColourLegend& legend, const render::Viewport& view);

} // namespace radiant::app
