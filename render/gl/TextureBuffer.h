#pragma once
// Move-only buffer texture of RGBA32F texels: per-patch (or per-vertex) data the shaders fetch by
// index with texelFetch. Works on the 3.3 core fallback too (RGB32F buffer textures need 4.0).
#include <epoxy/gl.h>

#include <glm/vec4.hpp>
#include <span>

namespace radiant::render::gl {

class TextureBuffer {
public:
    TextureBuffer();
    ~TextureBuffer();
    TextureBuffer(TextureBuffer&& other) noexcept;
    TextureBuffer& operator=(TextureBuffer&& other) noexcept;
    TextureBuffer(const TextureBuffer&) = delete;
    TextureBuffer& operator=(const TextureBuffer&) = delete;

    /// Replaces the contents. Same size: rewritten in place (glBufferSubData, which the driver pipelines
    /// without waiting for draws that read the old contents); new size: reallocated.
    void update(std::span<const glm::vec4> texels);
    [[nodiscard]] std::size_t size() const { return size_; }
    void bind(GLuint unit) const;

private:
    GLuint buffer_ = 0;
    GLuint texture_ = 0;
    std::size_t size_ = 0;
};

} // namespace radiant::render::gl
