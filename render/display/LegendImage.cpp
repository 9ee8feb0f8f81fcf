#include "render/display/LegendImage.h"

#include <algorithm>
#include <cmath>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
// Through its folder: render/ does not get the stb pkg-config include path (imgui brings it to app/ only).
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace radiant::render {

namespace {

// stb_easy_font's glyphs are about 7 units tall on a 12-unit line; a character advances ~6 units.
constexpr int kLineUnits = 12;

int textWidthUnits(const std::string& text) {
    std::vector<char> copy(text.begin(), text.end());
    copy.push_back('\0');
    return stb_easy_font_width(copy.data());
}

void blendPixel(ImageRgb8& image, int x, int y, glm::dvec3 colour, double alpha) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
    for (int c = 0; c < 3; ++c) {
        const double mixed = (1 - alpha) * image.pixels[i + static_cast<std::size_t>(c)] + alpha * 255.0 * colour[c];
        image.pixels[i + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::clamp(std::lround(mixed), 0L, 255L));
    }
}

void fillRect(ImageRgb8& image, int left, int top, int right, int bottom, glm::dvec3 colour, double alpha = 1.0) {
    for (int y = top; y < bottom; ++y)
        for (int x = left; x < right; ++x) blendPixel(image, x, y, colour, alpha);
}

/// stb_easy_font's quads (axis-aligned rectangles in glyph units) scaled and filled.
void paintText(ImageRgb8& image, int left, int top, int scale, const std::string& text, glm::dvec3 colour) {
    struct Vertex {
        float x, y, z;
        unsigned char rgba[4];
    };
    std::vector<Vertex> quads(text.size() * 70 * 4);  // stb's bound: at most ~270 bytes per character
    std::vector<char> copy(text.begin(), text.end());
    copy.push_back('\0');
    const int count = stb_easy_font_print(0, 0, copy.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(Vertex)));
    for (int q = 0; q < count; ++q) {
        const Vertex& a = quads[static_cast<std::size_t>(q) * 4];
        const Vertex& c = quads[static_cast<std::size_t>(q) * 4 + 2];
        fillRect(image, left + static_cast<int>(std::lround(a.x * static_cast<float>(scale))),
                 top + static_cast<int>(std::lround(a.y * static_cast<float>(scale))),
                 left + static_cast<int>(std::lround(c.x * static_cast<float>(scale))),
                 top + static_cast<int>(std::lround(c.y * static_cast<float>(scale))), colour);
    }
}

int barRow(const LegendLayout& layout, double position) {
    return layout.barBottom - 1 - static_cast<int>(std::lround(position * (layout.barBottom - 1 - layout.barTop)));
}

} // namespace

std::string legendTitle(const ColourLegend& legend) {
    return std::string(legend.quantity) + ", " + legend.unit + (legend.logScale ? ", log" : "");
}

LegendLayout layoutLegend(const ColourLegend& legend, int imageWidth, int imageHeight) {
    LegendLayout l;
    l.textScale = std::max(1, static_cast<int>(std::lround(imageHeight / 420.0)));
    const int s = l.textScale;
    const int margin = 8 * s, padding = 6 * s;
    int labelUnits = 0;
    for (const double tick : legend.ticksW_m2) labelUnits = std::max(labelUnits, textWidthUnits(formatLegendTick(tick)));
    const int titleWidth = textWidthUnits(legendTitle(legend)) * s;
    const int barWidth = 12 * s, tickLength = 4 * s;
    const int columnWidth = barWidth + tickLength + 3 * s + labelUnits * s;
    l.plateRight = imageWidth - margin;
    l.plateLeft = l.plateRight - std::max(titleWidth, columnWidth) - 2 * padding;
    l.plateTop = margin;
    l.barLeft = l.plateLeft + padding;
    l.barRight = l.barLeft + barWidth;
    l.barTop = l.plateTop + padding + kLineUnits * s + 4 * s + s * kLineUnits / 2;  // title, then room for the top label
    l.barBottom = l.barTop + std::max(8 * s, imageHeight * 2 / 5);
    l.plateBottom = l.barBottom + s * kLineUnits / 2 + padding;
    return l;
}

void paintLegend(ImageRgb8& image, const ColourLegend& legend) {
    const LegendLayout l = layoutLegend(legend, image.width, image.height);
    if (l.plateLeft < 0 || l.plateBottom > image.height) return;
    const int s = l.textScale;
    const glm::dvec3 text(0.93, 0.94, 0.96);
    fillRect(image, l.plateLeft, l.plateTop, l.plateRight, l.plateBottom, glm::dvec3(0.08, 0.09, 0.11), 0.82);
    paintText(image, l.barLeft, l.plateTop + 6 * s, s, legendTitle(legend), text);
    for (int y = l.barTop; y < l.barBottom; ++y) {
        const double position = 1.0 - static_cast<double>(y - l.barTop) / (l.barBottom - 1 - l.barTop);
        fillRect(image, l.barLeft, y, l.barRight, y + 1, viridis(position));
    }
    for (const double tick : legend.ticksW_m2) {
        const int y = barRow(l, legend.position(tick));
        fillRect(image, l.barRight, y - s / 2, l.barRight + 4 * s, y - s / 2 + s, text);
        // The glyphs' middle (about 3.5 units below their top) on the tick.
        paintText(image, l.barRight + 7 * s, y - (7 * s) / 2, s, formatLegendTick(tick), text);
    }
}

} // namespace radiant::render
