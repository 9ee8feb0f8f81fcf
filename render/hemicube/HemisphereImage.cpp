#include "render/hemicube/HemisphereImage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/hemicube/HemicubeGather.h"

namespace radiant::render {
namespace {

std::uint8_t toSrgbByte(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

const glm::vec3 kSky{0.012f, 0.014f, 0.02f};
const glm::vec3 kGrid{0.55f, 0.55f, 0.6f};
const glm::vec3 kOutline{1.0f, 0.8f, 0.0f};

} // namespace

glm::vec3 deltaFormFactorHeat(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    const glm::vec3 low{0.02f, 0.01f, 0.15f}, mid{0.02f, 0.35f, 0.35f}, high{1.0f, 0.85f, 0.05f};
    return t < 0.5f ? glm::mix(low, mid, t * 2.0f) : glm::mix(mid, high, t * 2.0f - 1.0f);
}

std::vector<std::uint8_t> hemisphereImage(const HemisphereViewMap& map, const HemicubeCapture& capture,
                                          const PatchMesh& mesh,
                                          std::span<const glm::vec3> surfaceColours, std::span<const Rgb> radiosity,
                                          const HemisphereImageOptions& options) {
    const int size = map.size();
    const HemicubeLayout& layout = capture.layout;
    const std::span<const std::uint32_t> items = capture.items;
    const std::vector<std::int64_t>& index = map.atlasIndex();
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4, 0);

    const auto surfaceAt = [&](std::size_t pixel) -> std::optional<std::size_t> {
        const std::int64_t atlas = index[pixel];
        if (atlas < 0) return std::nullopt;
        const std::uint32_t item = items[static_cast<std::size_t>(atlas)];
        if (item == kHemicubeEmpty) return std::nullopt;
        return mesh.patches[hemicubeItemPatch(item)].surface;
    };

    double scale = options.radianceScale;
    if (options.colouring == HemisphereColouring::Radiance && scale <= 0) {
        // Auto exposure: a few times the mean radiance seen, so a small bright light does not
        // leave every wall black; the tone curve below keeps the light from clipping harshly.
        double sum = 0;
        std::size_t count = 0;
        for (const std::uint32_t item : items)
            if (hemicubeItemIsFront(item) && !radiosity.empty()) {
                const Rgb& b = radiosity[hemicubeItemPatch(item)];
                sum += std::max({b.x, b.y, b.z});
                ++count;
            }
        scale = count > 0 ? 2.0 * sum / static_cast<double>(count) / std::numbers::pi : 0.0;
    }
    const double maxDeltaFormFactor = layout.pixelArea() / std::numbers::pi;

    const double lineHalfWidth = 0.8 / size;  // in disk units: about 0.8 px either side
    // The grid depends on the projection alone: its circles' radii and its spokes' directions are
    // worked out once, not per pixel (per-pixel trigonometry was most of this function's time, and
    // it runs on the drawing thread at every solver step while the dome shows radiance).
    std::array<double, 6> thetaRimRadius{};  // theta = 15, 30, ..., 90 degrees
    for (int k = 1; k <= 6; ++k) {
        const double theta = k * std::numbers::pi / 12.0;
        thetaRimRadius[static_cast<std::size_t>(k - 1)] =
            diskPointOfDirection(map.projection(), {std::sin(theta), 0.0, std::cos(theta)}).x;
    }
    std::array<glm::dvec2, 12> phiDirection{};  // phi = 0, 30, ..., 330 degrees
    for (int k = 0; k < 12; ++k) {
        const double phi = k * std::numbers::pi / 6.0;
        phiDirection[static_cast<std::size_t>(k)] = {std::cos(phi), std::sin(phi)};
    }
    for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
            const std::size_t pixel = static_cast<std::size_t>(row) * static_cast<std::size_t>(size) +
                                      static_cast<std::size_t>(column);
            const std::int64_t atlas = index[pixel];
            if (atlas < 0) continue;
            const std::uint32_t item = items[static_cast<std::size_t>(atlas)];
            glm::vec3 colour = kSky;
            switch (options.colouring) {
            case HemisphereColouring::Surfaces:
                if (item != kHemicubeEmpty) {
                    const Patch& patch = mesh.patches[hemicubeItemPatch(item)];
                    colour = patch.surface < surfaceColours.size() ? surfaceColours[patch.surface] : glm::vec3(0.5f);
                    // Shaded by the cosine at the surface, so walls of one colour read apart.
                    const std::size_t a = static_cast<std::size_t>(atlas);
                    const int w = layout.width();
                    const glm::dvec3 toward = glm::normalize(capture.frame.toWorld(
                        layout.pixelDirection(static_cast<int>(a % static_cast<std::size_t>(w)),
                                              static_cast<int>(a / static_cast<std::size_t>(w)))));
                    colour *= 0.45f + 0.55f * static_cast<float>(std::abs(glm::dot(toward, patch.normal)));
                    if (!hemicubeItemIsFront(item)) colour *= 0.25f;
                }
                break;
            case HemisphereColouring::Radiance:
                if (hemicubeItemIsFront(item) && !radiosity.empty() && scale > 0) {
                    const glm::vec3 c(radiosity[hemicubeItemPatch(item)] / (std::numbers::pi * scale));
                    colour = c / (glm::vec3(1.0f) + c);  // Reinhard
                }
                else if (item != kHemicubeEmpty)
                    colour = glm::vec3(0.0f);
                break;
            case HemisphereColouring::DeltaFormFactor:
                colour = deltaFormFactorHeat(static_cast<float>(layout.deltaFormFactors()[static_cast<std::size_t>(atlas)] /
                                                 maxDeltaFormFactor));
                break;
            }

            if (options.grid) {
                // In the disk's own coordinates (any rotation of the image leaves the grid the same).
                const glm::dvec2 p{(column + 0.5) / size * 2.0 - 1.0, 1.0 - (row + 0.5) / size * 2.0};
                const double radius = std::hypot(p.x, p.y);
                bool onGrid = false;
                for (const double rim : thetaRimRadius) onGrid = onGrid || std::abs(radius - rim) < lineHalfWidth;
                for (const glm::dvec2& d : phiDirection) {
                    const double along = p.x * d.x + p.y * d.y;
                    const double across = -p.x * d.y + p.y * d.x;
                    onGrid = onGrid || (along > 0 && std::abs(across) < lineHalfWidth);
                }
                if (onGrid) colour = glm::mix(colour, kGrid, 0.6f);
            }

            if (options.targetSurface && surfaceAt(pixel) == options.targetSurface) {
                // An edge pixel of the target: some 4-neighbour shows something else.
                const auto differs = [&](int c, int r) {
                    if (c < 0 || r < 0 || c >= size || r >= size) return true;
                    const std::size_t neighbour = static_cast<std::size_t>(r) * static_cast<std::size_t>(size) +
                                                  static_cast<std::size_t>(c);
                    return index[neighbour] < 0 || surfaceAt(neighbour) != options.targetSurface;
                };
                if (differs(column - 1, row) || differs(column + 1, row) || differs(column, row - 1) ||
                    differs(column, row + 1))
                    colour = kOutline;
            }
            rgba[pixel * 4 + 0] = toSrgbByte(colour.x);
            rgba[pixel * 4 + 1] = toSrgbByte(colour.y);
            rgba[pixel * 4 + 2] = toSrgbByte(colour.z);
            rgba[pixel * 4 + 3] = item == kHemicubeEmpty ? options.openSkyAlpha : std::uint8_t{255};
        }
    return rgba;
}

} // namespace radiant::render
