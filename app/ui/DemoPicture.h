#pragma once
// A lecture demo in the 3D view: its picture for the pointer's ray (when the pointer is over the
// view), drawn by the demo renderer, then its labels (render/demo/DemoDrawing.h) written over it,
// each at the pixel its anchor projects to, in the UI's font (so a projector's UI scale enlarges them), on a dark backing
// so they read over the false-colour plane and the bright Sun alike; a label whose anchor is on
// screen is kept inside the view whole, one whose anchor is not is left out. Behind the sidebar and the
// caption, which are ImGui windows.
#include "render/camera/Camera.h"
#include "render/demo/DemoDrawing.h"
#include "render/demo/DemoRenderer.h"

namespace radiant::app {

class LectureDemo;

/// Draws `demo` into the bound framebuffer's scene viewport and queues its labels; call between
/// ImGuiLayer::newFrame and render. `uiScale` widens its lines with the text.
void drawDemoPicture(const LectureDemo& demo, render::DemoRenderer& renderer, const render::Camera& camera,
                     const render::Viewport& viewport, float pixelRatio, float uiScale);

/// Call between ImGuiLayer::newFrame and render; `viewport` in framebuffer pixels, `pixelRatio`
/// framebuffer pixels per UI unit.
void drawDemoLabels(const render::DemoDrawing& drawing, const render::Camera& camera, const render::Viewport& viewport,
                    float pixelRatio);

} // namespace radiant::app
