#include "app/ui/DemoPicture.h"

#include <imgui.h>

#include <algorithm>
#include <optional>

#include "app/panels/demos/LectureDemo.h"
#include "app/ui/LabelLayout.h"
#include "app/window/PickRay.h"

namespace radiant::app {

void drawDemoLabels(const render::DemoDrawing& drawing, const render::Camera& camera, const render::Viewport& viewport,
                    float pixelRatio) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const float font = ImGui::GetFontSize();
    const float pad = 0.2f * font;
    // The 3D view's rectangle in UI units: labels that would spill over its edges are pulled inside.
    const float left = static_cast<float>(viewport.x) / pixelRatio, top = static_cast<float>(viewport.y) / pixelRatio;
    const float right = left + static_cast<float>(viewport.width) / pixelRatio,
                bottom = top + static_cast<float>(viewport.height) / pixelRatio;
    std::vector<const render::DemoLabel*> shown;
    std::vector<ui::LabelBox> boxes;  // the text's rectangles: their backgrounds may touch
    for (const render::DemoLabel& label : drawing.labels) {
        const glm::dvec3 p = render::projectToPixel(camera, viewport, glm::dvec3(label.anchor));
        if (p.z <= 0 || p.z >= 1) continue;  // behind the eye or beyond the far plane
        // An anchor out of the view is not on screen: its label would point at nothing.
        if (p.x < viewport.x || p.y < viewport.y || p.x > viewport.x + viewport.width || p.y > viewport.y + viewport.height)
            continue;
        const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
        ImVec2 at{static_cast<float>(p.x) / pixelRatio - (label.endsAtAnchor ? size.x : 0.0f),
                  static_cast<float>(p.y) / pixelRatio - 0.5f * size.y};
        at.x = std::clamp(at.x, left + pad, std::max(left + pad, right - size.x - pad));
        at.y = std::clamp(at.y, top + pad, std::max(top + pad, bottom - size.y - pad));
        shown.push_back(&label);
        boxes.push_back({at.x, at.y, size.x, size.y, label.pinned});
    }
    ui::separateLabels(boxes, top + pad, bottom - pad, 2.0f * pad);
    draw->PushClipRect({left, top}, {right, bottom});
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const render::DemoLabel& label = *shown[i];
        const ImVec2 at{boxes[i].x, boxes[i].y};
        draw->AddRectFilled({at.x - pad, at.y - pad}, {at.x + boxes[i].width + pad, at.y + boxes[i].height + pad},
                            IM_COL32(10, 12, 16, 190), pad);
        draw->AddText(at, ImGui::ColorConvertFloat4ToU32({label.colour.x, label.colour.y, label.colour.z, label.colour.w}),
                      label.text.c_str());
    }
    draw->PopClipRect();
}

void drawDemoPicture(const LectureDemo& demo, render::DemoRenderer& renderer, const render::Camera& camera,
                     const render::Viewport& viewport, float pixelRatio, float uiScale) {
    std::optional<PickRay> cursor;
    const ImGuiIO& io = ImGui::GetIO();
    const glm::dvec2 pointer{io.MousePos.x * pixelRatio, io.MousePos.y * pixelRatio};
    if (ImGui::IsMousePosValid() && !io.WantCaptureMouse && pointer.x >= viewport.x && pointer.y >= viewport.y &&
        pointer.x < viewport.x + viewport.width && pointer.y < viewport.y + viewport.height)
        cursor = pickRay(camera, viewport, pointer);
    const render::DemoDrawing picture = demo.picture(cursor);
    renderer.set(picture, uiScale * pixelRatio);
    renderer.draw(camera, viewport.aspect());
    drawDemoLabels(picture, camera, viewport, pixelRatio);
}

} // namespace radiant::app
