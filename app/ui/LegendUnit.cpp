#include "app/ui/LegendUnit.h"

#include <cstring>

namespace radiant::app {

const char* legendUnitForScreen(const render::ColourLegend& legend) {
    // The PNG legend's bitmap font has no superscript; the UI font does.
    return std::strcmp(legend.unit, render::kFalseColourUnit) == 0 ? "W/m\xC2\xB2" : legend.unit;
}

} // namespace radiant::app
