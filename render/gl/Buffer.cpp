#include "render/gl/Buffer.h"

#include <utility>

#include "radiometry/common/Check.h"
#include "render/gl/ScopedBinding.h"

namespace radiant::render::gl {

Buffer::Buffer() { glGenBuffers(1, &id_); }

Buffer::~Buffer() {
    if (id_ != 0) glDeleteBuffers(1, &id_);
}

Buffer::Buffer(Buffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), byteSize_(std::exchange(other.byteSize_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) glDeleteBuffers(1, &id_);
        id_ = std::exchange(other.id_, 0);
        byteSize_ = std::exchange(other.byteSize_, 0);
    }
    return *this;
}

void Buffer::setData(std::span<const std::byte> bytes, GLenum usage) {
    const ScopedArrayBuffer bound(id_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes.size()), bytes.data(), usage);
    byteSize_ = bytes.size();
}

void Buffer::setSubData(std::size_t offsetBytes, std::span<const std::byte> bytes) {
    RADIANT_CHECK_LE(offsetBytes + bytes.size(), byteSize_);
    if (bytes.empty()) return;
    const ScopedArrayBuffer bound(id_);
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(offsetBytes), static_cast<GLsizeiptr>(bytes.size()),
                    bytes.data());
}

} // namespace radiant::render::gl
