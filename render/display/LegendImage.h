#pragma once
// The false-colour legend painted into a picture (`radiant render --false-colour --png`): a vertical
// viridis bar, maximum at the top, ticks and their labels, the quantity and unit as a title, on a dark
// plate in the top-right corner. Drawn on the CPU into the read-back image, so a headless render and
// the unit tests get the same pixels; text in stb_easy_font's vector glyphs (Debian's libstb-dev).
#include <string>

#include "render/ColourScale.h"
#include "render/ImageRgb8.h"

namespace radiant::render {

/// Where the legend's parts land in a picture of a given size (pixels, top row 0).
struct LegendLayout {
    int plateLeft = 0, plateTop = 0, plateRight = 0, plateBottom = 0;  ///< the dark plate behind it all
    int barLeft = 0, barTop = 0, barRight = 0, barBottom = 0;          ///< the colour bar; top row = maximum
    int textScale = 1;  ///< stb_easy_font pixels per glyph unit: grows with the picture, readable when printed
};

/// The title line: "radiosity, sum of R+G+B, W/m^2" (plus ", log" for a log legend).
std::string legendTitle(const ColourLegend& legend);

LegendLayout layoutLegend(const ColourLegend& legend, int imageWidth, int imageHeight);

/// Paints the legend over `image` (which keeps its size); a picture too small for it is left alone.
void paintLegend(ImageRgb8& image, const ColourLegend& legend);

} // namespace radiant::render
