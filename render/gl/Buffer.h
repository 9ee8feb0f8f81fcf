#pragma once
// Move-only owner of a GL buffer object (as Magnum's GL::Buffer): the name is deleted exactly once.
// Bind-to-edit calls rather than DSA, so the 3.3 core fallback context works too.
#include <epoxy/gl.h>

#include <cstddef>
#include <span>

namespace radiant::render::gl {

class Buffer {
public:
    Buffer();
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    [[nodiscard]] GLuint id() const { return id_; }
    [[nodiscard]] std::size_t byteSize() const { return byteSize_; }

    // Edits bind the buffer to GL_ARRAY_BUFFER and restore what was bound there before.

    /// Replaces the whole contents and size.
    void setData(std::span<const std::byte> bytes, GLenum usage = GL_STATIC_DRAW);
    /// Overwrites bytes [offset, offset + size) of the contents; they must lie inside byteSize(),
    /// else InvariantError.
    void setSubData(std::size_t offsetBytes, std::span<const std::byte> bytes);

    template <class T>
    void setData(std::span<const T> items, GLenum usage = GL_STATIC_DRAW) {
        setData(std::as_bytes(items), usage);
    }
    template <class T>
    void setSubData(std::size_t offsetBytes, std::span<const T> items) {
        setSubData(offsetBytes, std::as_bytes(items));
    }

private:
    GLuint id_ = 0;
    std::size_t byteSize_ = 0;
};

} // namespace radiant::render::gl
