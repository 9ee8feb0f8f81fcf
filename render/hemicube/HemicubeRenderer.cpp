#include "render/hemicube/HemicubeRenderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/hemicube/HemicubeGather.h"
#include "render/gl/Buffer.h"
#include "render/gl/ShaderProgram.h"
#include "render/gl/StateGuard.h"
#include "render/gl/VertexArray.h"

namespace radiant::render {
namespace {

struct ItemVertex {
    glm::vec3 position;
    glm::vec3 normal;
    std::uint32_t item;
};

/// An integer colour target (the items) and a float depth buffer, sized for one resolution.
struct ItemTarget {
    GLuint framebuffer = 0, items = 0, depth = 0;
    int width = 0, height = 0;

    ItemTarget(int w, int h) : width(w), height(h) {
        glGenTextures(1, &items);
        glBindTexture(GL_TEXTURE_2D, items);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, w, h, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        glGenRenderbuffers(1, &depth);
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, w, h);
        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, items, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            release();
            throw RadiantError({"hemicube", std::to_string(w) + " x " + std::to_string(h) + " item buffer"},
                               "framebuffer incomplete, status " + std::to_string(status));
        }
    }
    ~ItemTarget() { release(); }
    ItemTarget(const ItemTarget&) = delete;
    ItemTarget& operator=(const ItemTarget&) = delete;

    void release() {
        if (framebuffer != 0) glDeleteFramebuffers(1, &framebuffer);
        if (depth != 0) glDeleteRenderbuffers(1, &depth);
        if (items != 0) glDeleteTextures(1, &items);
        framebuffer = depth = items = 0;
    }
};

} // namespace

struct HemicubeRenderer::GlState {
    gl::ShaderProgram program{"hemicube.vert.glsl", "hemicube.frag.glsl"};
    gl::Buffer vertices;
    gl::VertexArray layout;
    GLsizei vertexCount = 0;
    std::optional<ItemTarget> target;
};

HemicubeRenderer::HemicubeRenderer(const PatchMesh& mesh) : gl_(std::make_unique<GlState>()), patchCount_(mesh.size()) {
    std::vector<ItemVertex> triangles;
    triangles.reserve(mesh.size() * 6);
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        const std::uint32_t item = encodeHemicubeItem(p, false);
        const auto vertex = [&](int corner) {
            const glm::dvec3& v = mesh.vertices[patch.corners[static_cast<std::size_t>(corner)]];
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
            return ItemVertex{glm::vec3(v), glm::vec3(patch.normal), item};
        };
        for (int corner = 1; corner + 1 < patch.cornerCount; ++corner) {
            triangles.push_back(vertex(0));
            triangles.push_back(vertex(corner));
            triangles.push_back(vertex(corner + 1));
        }
    }
    if (!mesh.patches.empty()) sceneSize_ = std::max(glm::length(hi - lo), 1e-6);
    gl_->vertices.setData(std::span<const ItemVertex>(triangles));
    gl_->vertexCount = static_cast<GLsizei>(triangles.size());
    constexpr std::size_t stride = sizeof(ItemVertex);
    gl_->layout.addFloatAttribute(gl_->vertices, 0, 3, stride, offsetof(ItemVertex, position));
    gl_->layout.addFloatAttribute(gl_->vertices, 1, 3, stride, offsetof(ItemVertex, normal));
    gl_->layout.bind();
    glBindBuffer(GL_ARRAY_BUFFER, gl_->vertices.id());
    glEnableVertexAttribArray(2);
    // The offset is a byte count GL takes as a pointer: the API's own convention.
    glVertexAttribIPointer(2, 1, GL_UNSIGNED_INT, static_cast<GLsizei>(stride),
                           reinterpret_cast<const void*>(offsetof(ItemVertex, item)));  // NOLINT
    glBindVertexArray(0);
}

HemicubeRenderer::~HemicubeRenderer() = default;
HemicubeRenderer::HemicubeRenderer(HemicubeRenderer&&) noexcept = default;
HemicubeRenderer& HemicubeRenderer::operator=(HemicubeRenderer&&) noexcept = default;

void HemicubeRenderer::render(const glm::dvec3& x, const HemicubeFrame& frame, const HemicubeLayout& layout) {
    if (!gl_->target || gl_->target->width != layout.width() || gl_->target->height != layout.height())
        gl_->target.emplace(layout.width(), layout.height());
    // Lifted off its own surface, which then lies just below the horizon instead of on it; the near
    // plane is far smaller than any patch, the depth buffer float.
    const glm::dvec3 eye = x + frame.normal() * (1e-5 * sceneSize_);
    const double nearPlane = 1e-4 * sceneSize_, farPlane = 4.0 * sceneSize_;

    glBindFramebuffer(GL_FRAMEBUFFER, gl_->target->framebuffer);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);  // back faces still occlude; the shader marks them
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);  // a caller that left depth writes off would leave the clear below undone
    const GLuint empty[4] = {kHemicubeEmpty, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, empty);
    glClear(GL_DEPTH_BUFFER_BIT);

    gl_->program.use();
    gl_->program.set("eye", glm::vec3(eye));
    gl_->layout.bind();
    for (const HemicubeFaceView& face : layout.faces()) {
        const glm::dvec3 forward = frame.toWorld(face.forward), up = frame.toWorld(face.up),
                         right = frame.toWorld(face.right);
        // Rows: right, up, -forward (a rotation, so windings keep their sense); then the eye.
        glm::dmat4 view(1.0);
        for (int c = 0; c < 3; ++c) {
            view[c][0] = right[c];
            view[c][1] = up[c];
            view[c][2] = -forward[c];
        }
        view[3] = glm::dvec4(-glm::dot(right, eye), -glm::dot(up, eye), glm::dot(forward, eye), 1.0);
        // A 90 degree frustum; the sides keep only its upper half (bottom at the horizon).
        const glm::dmat4 projection =
            glm::frustum(-nearPlane, nearPlane, face.bottom * nearPlane, nearPlane, nearPlane, farPlane);
        gl_->program.set("viewProjection", glm::mat4(projection * view));
        glViewport(0, face.firstRow, layout.width(), face.rows);
        glDrawArrays(GL_TRIANGLES, 0, gl_->vertexCount);
    }
}

HemicubeCapture HemicubeRenderer::capture(const glm::dvec3& x, const glm::dvec3& n, int resolution) {
    const gl::StateGuard saved;
    const HemicubeFrame frame(n);
    HemicubeCapture result{HemicubeLayout(resolution), x, frame.normal(), frame, {}};
    render(x, frame, result.layout);
    result.items.resize(result.layout.pixelCount());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->target->framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, result.layout.width(), result.layout.height(), GL_RED_INTEGER, GL_UNSIGNED_INT,
                 result.items.data());
    return result;
}

void HemicubeRenderer::renderOnly(const glm::dvec3& x, const glm::dvec3& n, int resolution) {
    const gl::StateGuard saved;
    render(x, HemicubeFrame(n), HemicubeLayout(resolution));
    glFinish();
}

} // namespace radiant::render
