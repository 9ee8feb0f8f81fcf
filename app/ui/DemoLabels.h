#pragma once
// A lecture demo's labels (render/demo/DemoDrawing.h) written over the 3D view: each at the pixel its
// anchor projects to, in the UI's font (so a projector's UI scale enlarges them), on a dark backing
// so they read over the false-colour plane and the bright Sun alike; a label whose anchor is on
// screen is kept inside the view whole, one whose anchor is not is left out. Behind the sidebar and the
// caption, which are ImGui windows.
#include "render/camera/Camera.h"
#include "render/demo/DemoDrawing.h"

namespace radiant::app {

/// Call between ImGuiLayer::newFrame and render; `viewport` in framebuffer pixels, `pixelRatio`
/// framebuffer pixels per UI unit.
void drawDemoLabels(const render::DemoDrawing& drawing, const render::Camera& camera, const render::Viewport& viewport,
                    float pixelRatio);

} // namespace radiant::app
