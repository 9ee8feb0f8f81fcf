#pragma once
// The false-colour legend's unit as the UI writes it (the Display panel, the 3D view's legend).
#include "render/ColourScale.h"

namespace radiant::app {

/// "W/m²" for the radiometric default, else the legend's unit as given.
const char* legendUnitForScreen(const render::ColourLegend& legend);

} // namespace radiant::app
