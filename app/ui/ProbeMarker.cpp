#include "app/ui/ProbeMarker.h"

#include <imgui.h>

#include <utility>

#include "render/overlay/DepthVisibility.h"

namespace radiant::app {

void drawProbeMarker(const render::Camera& camera, const render::Viewport& viewport, int framebufferHeight,
                     float pixelRatio, const glm::dvec3& point) {
    const glm::dvec3 p = render::projectToPixel(camera, viewport, point);
    if (p.z <= 0 || p.z >= 1) return;
    // Behind a block, the picked point is not there to see.
    if (!render::visibleInDepthBuffer(camera, viewport, framebufferHeight, point)) return;
    const ImVec2 centre{static_cast<float>(p.x) / pixelRatio, static_cast<float>(p.y) / pixelRatio};
    const float r = ImGui::GetFontSize() * 0.45f;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    // Dark under light: readable on the white walls and on the black shadows alike.
    for (const auto& [colour, thickness] : {std::pair{IM_COL32(0, 0, 0, 200), 4.0f}, std::pair{IM_COL32(255, 230, 80, 255), 2.0f}}) {
        draw->AddCircle(centre, r, colour, 24, thickness);
        draw->AddLine({centre.x - 2 * r, centre.y}, {centre.x - r, centre.y}, colour, thickness);
        draw->AddLine({centre.x + r, centre.y}, {centre.x + 2 * r, centre.y}, colour, thickness);
        draw->AddLine({centre.x, centre.y - 2 * r}, {centre.x, centre.y - r}, colour, thickness);
        draw->AddLine({centre.x, centre.y + r}, {centre.x, centre.y + 2 * r}, colour, thickness);
    }
}

} // namespace radiant::app
