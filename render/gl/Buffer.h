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

    /// Replaces the whole contents (GL_ARRAY_BUFFER target; the buffer is left bound there).
    void setData(std::span<const std::byte> bytes, GLenum usage = GL_STATIC_DRAW);

    template <class T>
    void setData(std::span<const T> items, GLenum usage = GL_STATIC_DRAW) {
        setData(std::as_bytes(items), usage);
    }

private:
    GLuint id_ = 0;
    std::size_t byteSize_ = 0;
};

} // namespace radiant::render::gl
