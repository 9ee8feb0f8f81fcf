#pragma once
// Move-only owner of a vertex array object: which buffers feed which shader inputs.
#include <epoxy/gl.h>

#include <cstddef>

#include "render/gl/Buffer.h"

namespace radiant::render::gl {

class VertexArray {
public:
    VertexArray();
    ~VertexArray();
    VertexArray(VertexArray&& other) noexcept;
    VertexArray& operator=(VertexArray&& other) noexcept;
    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;

    [[nodiscard]] GLuint id() const { return id_; }
    void bind() const;

    /// Feeds shader input `location` with `components` floats per vertex read from `buffer`
    /// at `offsetBytes` within each `strideBytes` record.
    void addFloatAttribute(const Buffer& buffer, GLuint location, GLint components, std::size_t strideBytes,
                           std::size_t offsetBytes);
    /// As addFloatAttribute for one 32-bit signed integer per vertex, read as an `int` shader input.
    void addIntAttribute(const Buffer& buffer, GLuint location, std::size_t strideBytes, std::size_t offsetBytes);

    /// Draws through `buffer`'s indices (glDrawElements): the vertex array records it.
    void setIndexBuffer(const Buffer& buffer);

private:
    GLuint id_ = 0;
};

} // namespace radiant::render::gl
