#pragma once
// Draws a lecture demo's picture (render/demo/DemoDrawing.h) in the 3D view in place of the
// radiosity scene: its triangles two-sided (opaque ones first, then the see-through ones without
// writing depth), isolines where a triangle's contour coordinate crosses an integer, and its segments
// as screen-space quads of a width in pixels (core GL has no wide lines). The labels are the lab's to
// write (ImGui). The drawing is small (thousands of vertices), so set() uploads it whole each time.
// GL-free header; create, use and destroy on the GL thread.
#include <memory>

#include "render/SceneRenderer.h"
#include "render/demo/DemoDrawing.h"

namespace radiant::render {

class DemoRenderer final : public SceneRenderer {
public:
    /// Compiles the shaders. Needs a current GL context.
    DemoRenderer();
    ~DemoRenderer() override;
    DemoRenderer(DemoRenderer&&) noexcept;
    DemoRenderer& operator=(DemoRenderer&&) noexcept;
    DemoRenderer(const DemoRenderer&) = delete;
    DemoRenderer& operator=(const DemoRenderer&) = delete;

    /// Uploads the drawing's triangles and segments; `lineScale` multiplies every segment's width
    /// (the UI scale times the framebuffer's pixel ratio, so lines keep step with the text).
    void set(const DemoDrawing& drawing, float lineScale = 1.0f);
    /// Draws into the bound framebuffer's viewport; restores the GL state it changes.
    void draw(const Camera& camera, double aspect) const override;

private:
    struct Gpu;
    std::unique_ptr<Gpu> gpu_;
};

} // namespace radiant::render
