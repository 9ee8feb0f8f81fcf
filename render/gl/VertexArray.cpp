#include "render/gl/VertexArray.h"

#include "render/gl/ScopedBinding.h"

#include <utility>

namespace radiant::render::gl {

VertexArray::VertexArray() { glGenVertexArrays(1, &id_); }

VertexArray::~VertexArray() {
    if (id_ != 0) glDeleteVertexArrays(1, &id_);
}

VertexArray::VertexArray(VertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) glDeleteVertexArrays(1, &id_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void VertexArray::bind() const { glBindVertexArray(id_); }

void VertexArray::addFloatAttribute(const Buffer& buffer, GLuint location, GLint components, std::size_t strideBytes,
                                    std::size_t offsetBytes) {
    // The vertex array records the buffer bound at glVertexAttribPointer; both bindings are put back.
    const ScopedVertexArray array(id_);
    const ScopedArrayBuffer bound(buffer.id());
    glEnableVertexAttribArray(location);
    // GL takes the offset into the bound buffer disguised as a pointer.
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(strideBytes),
                          reinterpret_cast<const void*>(offsetBytes));  // NOLINT
}

void VertexArray::addIntAttribute(const Buffer& buffer, GLuint location, std::size_t strideBytes,
                                  std::size_t offsetBytes) {
    // The vertex array records the buffer bound at glVertexAttribPointer; both bindings are put back.
    const ScopedVertexArray array(id_);
    const ScopedArrayBuffer bound(buffer.id());
    glEnableVertexAttribArray(location);
    glVertexAttribIPointer(location, 1, GL_INT, static_cast<GLsizei>(strideBytes),
                           reinterpret_cast<const void*>(offsetBytes));  // NOLINT
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    // The element binding is the vertex array's own state: nothing else to put back.
    const ScopedVertexArray array(id_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());
}

} // namespace radiant::render::gl
