#include "render/demo/DemoRenderer.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/StateGuard.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {
namespace {

/// One corner of a segment's quad: both ends ride along, so the vertex shader can find the
/// segment's direction on screen and push this corner out sideways by half the width.
struct LineCorner {
    glm::vec3 from, to;
    glm::vec4 colour;
    glm::vec2 corner;  ///< x: 0 at `from`, 1 at `to`; y: -1 or +1, the side
    float widthPixels;
};

std::vector<LineCorner> lineCorners(const std::vector<DemoSegment>& segments, float scale) {
    std::vector<LineCorner> corners;
    corners.reserve(segments.size() * 6);
    for (const DemoSegment& s : segments) {
        const auto at = [&](float end, float side) { return LineCorner{s.from, s.to, s.colour, {end, side}, s.widthPixels * scale}; };
        corners.insert(corners.end(), {at(0, -1), at(1, -1), at(1, 1), at(0, -1), at(1, 1), at(0, 1)});
    }
    return corners;
}

} // namespace

struct DemoRenderer::Gpu {
    gl::ShaderProgram surfaces{"demo.vert.glsl", "demo.frag.glsl"};
    gl::ShaderProgram lines{"demo_line.vert.glsl", "demo.frag.glsl"};
    gl::Buffer triangleBuffer, lineBuffer;
    gl::VertexArray triangleLayout, lineLayout;
    GLsizei opaqueCount = 0, seeThroughCount = 0, lineCount = 0;
};

DemoRenderer::DemoRenderer() : gpu_(std::make_unique<Gpu>()) {
    Gpu& g = *gpu_;
    // Layouts point at the buffers once; set() refills the buffers in place.
    g.triangleBuffer.setData(std::span<const DemoVertex>(), GL_DYNAMIC_DRAW);
    g.triangleLayout.addFloatAttribute(g.triangleBuffer, 0, 3, sizeof(DemoVertex), offsetof(DemoVertex, position));
    g.triangleLayout.addFloatAttribute(g.triangleBuffer, 1, 4, sizeof(DemoVertex), offsetof(DemoVertex, colour));
    g.triangleLayout.addFloatAttribute(g.triangleBuffer, 2, 1, sizeof(DemoVertex), offsetof(DemoVertex, contour));
    g.lineBuffer.setData(std::span<const LineCorner>(), GL_DYNAMIC_DRAW);
    g.lineLayout.addFloatAttribute(g.lineBuffer, 0, 3, sizeof(LineCorner), offsetof(LineCorner, from));
    g.lineLayout.addFloatAttribute(g.lineBuffer, 1, 3, sizeof(LineCorner), offsetof(LineCorner, to));
    g.lineLayout.addFloatAttribute(g.lineBuffer, 2, 4, sizeof(LineCorner), offsetof(LineCorner, colour));
    g.lineLayout.addFloatAttribute(g.lineBuffer, 3, 2, sizeof(LineCorner), offsetof(LineCorner, corner));
    g.lineLayout.addFloatAttribute(g.lineBuffer, 4, 1, sizeof(LineCorner), offsetof(LineCorner, widthPixels));
    glBindVertexArray(0);
}

DemoRenderer::~DemoRenderer() = default;
DemoRenderer::DemoRenderer(DemoRenderer&&) noexcept = default;
DemoRenderer& DemoRenderer::operator=(DemoRenderer&&) noexcept = default;

void DemoRenderer::set(const DemoDrawing& drawing, float lineScale) {
    Gpu& g = *gpu_;
    // Opaque triangles first: the see-through ones (cones, veils) blend over everything behind them.
    std::vector<DemoVertex> ordered;
    ordered.reserve(drawing.triangles.size());
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i + 2 < drawing.triangles.size(); i += 3) {
            const bool opaque = drawing.triangles[i].colour.w >= 1.0f;
            if (opaque != (pass == 0)) continue;
            ordered.insert(ordered.end(), drawing.triangles.begin() + static_cast<std::ptrdiff_t>(i),
                           drawing.triangles.begin() + static_cast<std::ptrdiff_t>(i + 3));
        }
    std::size_t opaque = 0;
    for (std::size_t i = 0; i + 2 < drawing.triangles.size(); i += 3) opaque += drawing.triangles[i].colour.w >= 1.0f ? 3 : 0;
    g.opaqueCount = static_cast<GLsizei>(opaque);
    g.seeThroughCount = static_cast<GLsizei>(ordered.size() - opaque);
    g.triangleBuffer.setData(std::span<const DemoVertex>(ordered), GL_DYNAMIC_DRAW);
    const std::vector<LineCorner> corners = lineCorners(drawing.segments, lineScale);
    g.lineBuffer.setData(std::span<const LineCorner>(corners), GL_DYNAMIC_DRAW);
    g.lineCount = static_cast<GLsizei>(corners.size());
}

void DemoRenderer::draw(const Camera& camera, double aspect) const {
    const gl::StateGuard saved;
    const Gpu& g = *gpu_;
    const glm::mat4 viewProjection(camera.viewProjection(aspect));
    GLint viewport[4]{};
    glGetIntegerv(GL_VIEWPORT, viewport);

    glDisable(GL_CULL_FACE);  // a demo's plates and planes are seen from either side
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    g.surfaces.use();
    g.surfaces.set("viewProjection", viewProjection);
    g.triangleLayout.bind();
    glDepthMask(GL_TRUE);
    if (g.opaqueCount > 0) glDrawArrays(GL_TRIANGLES, 0, g.opaqueCount);
    glDepthMask(GL_FALSE);
    if (g.seeThroughCount > 0) glDrawArrays(GL_TRIANGLES, g.opaqueCount, g.seeThroughCount);
    glDepthMask(GL_TRUE);

    if (g.lineCount == 0) return;
    g.lines.use();
    g.lines.set("viewProjection", viewProjection);
    g.lines.set("viewportPixels", glm::vec2(static_cast<float>(viewport[2]), static_cast<float>(viewport[3])));
    g.lineLayout.bind();
    glDrawArrays(GL_TRIANGLES, 0, g.lineCount);
}

} // namespace radiant::render
