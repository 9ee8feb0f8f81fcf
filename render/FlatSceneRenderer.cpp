#include "render/FlatSceneRenderer.h"

#include <cstddef>
#include <glm/geometric.hpp>

#include "render/SceneTriangles.h"
#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {

struct FlatSceneRenderer::GlState {
    gl::ShaderProgram program{"flat.vert.glsl", "flat.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
};

FlatSceneRenderer::FlatSceneRenderer(const Scene& scene) : gl_(std::make_unique<GlState>()) {
    const std::vector<FlatVertex> triangles = flatTriangles(scene);
    gl_->vertices.setData(std::span<const FlatVertex>(triangles));
    gl_->vertexCount = static_cast<GLsizei>(triangles.size());
    constexpr std::size_t stride = sizeof(FlatVertex);
    gl_->layout.addFloatAttribute(gl_->vertices, 0, 3, stride, offsetof(FlatVertex, position));
    gl_->layout.addFloatAttribute(gl_->vertices, 1, 3, stride, offsetof(FlatVertex, normal));
    gl_->layout.addFloatAttribute(gl_->vertices, 2, 3, stride, offsetof(FlatVertex, colour));
    gl_->layout.addFloatAttribute(gl_->vertices, 3, 1, stride, offsetof(FlatVertex, emissive));
    glBindVertexArray(0);
}

FlatSceneRenderer::~FlatSceneRenderer() = default;
FlatSceneRenderer::FlatSceneRenderer(FlatSceneRenderer&&) noexcept = default;
FlatSceneRenderer& FlatSceneRenderer::operator=(FlatSceneRenderer&&) noexcept = default;

std::size_t FlatSceneRenderer::triangleCount() const { return static_cast<std::size_t>(gl_->vertexCount / 3); }

void FlatSceneRenderer::draw(const Camera& camera, double aspect) const {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // walls are seen from inside, blocks from outside: both sides are real
    gl_->program.use();
    gl_->program.set("viewProjection", glm::mat4(camera.viewProjection(aspect)));
    gl_->program.set("eye", glm::vec3(camera.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const glm::dvec3 up = glm::cross(right, camera.forward);
    gl_->program.set("keyDirection", glm::vec3(glm::normalize(-camera.forward + 0.8 * up + 0.6 * right)));
    // Pushed back by their depth slope so overlays (patch edges) drawn at the same depth stay on top.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    gl_->layout.bind();
    glDrawArrays(GL_TRIANGLES, 0, gl_->vertexCount);
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

} // namespace radiant::render
