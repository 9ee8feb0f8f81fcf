#include "render/WireframeRenderer.h"

#include <glm/vec3.hpp>
#include <vector>

#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {

struct WireframeRenderer::GlState {
    gl::ShaderProgram program{"wire.vert.glsl", "wire.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
};

WireframeRenderer::WireframeRenderer(const PatchMesh& mesh) : gl_(std::make_unique<GlState>()) {
    std::vector<glm::vec3> lines;
    lines.reserve(mesh.patches.size() * 8);
    for (const Patch& patch : mesh.patches)
        for (std::uint8_t i = 0; i < patch.cornerCount; ++i) {
            lines.emplace_back(mesh.vertices[patch.corners[i]]);
            lines.emplace_back(mesh.vertices[patch.corners[(i + 1) % patch.cornerCount]]);
        }
    gl_->vertices.setData(std::span<const glm::vec3>(lines));
    gl_->vertexCount = static_cast<GLsizei>(lines.size());
    gl_->layout.addFloatAttribute(gl_->vertices, 0, 3, sizeof(glm::vec3), 0);
    glBindVertexArray(0);
}

WireframeRenderer::~WireframeRenderer() = default;
WireframeRenderer::WireframeRenderer(WireframeRenderer&&) noexcept = default;
WireframeRenderer& WireframeRenderer::operator=(WireframeRenderer&&) noexcept = default;

void WireframeRenderer::draw(const Camera& camera, double aspect) const {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl_->program.use();
    gl_->program.set("viewProjection", glm::mat4(camera.viewProjection(aspect)));
    gl_->program.set("colour", glm::vec4(0.08f, 0.09f, 0.11f, 0.55f));
    gl_->layout.bind();
    glDrawArrays(GL_LINES, 0, gl_->vertexCount);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

} // namespace radiant::render
