#include "render/gl/TextureBuffer.h"

#include <utility>

namespace radiant::render::gl {

TextureBuffer::TextureBuffer() {
    glGenBuffers(1, &buffer_);
    glGenTextures(1, &texture_);
}

TextureBuffer::~TextureBuffer() {
    if (texture_ != 0) glDeleteTextures(1, &texture_);
    if (buffer_ != 0) glDeleteBuffers(1, &buffer_);
}

TextureBuffer::TextureBuffer(TextureBuffer&& other) noexcept
    : buffer_(std::exchange(other.buffer_, 0)), texture_(std::exchange(other.texture_, 0)),
      size_(std::exchange(other.size_, 0)) {}

TextureBuffer& TextureBuffer::operator=(TextureBuffer&& other) noexcept {
    if (this != &other) {
        if (texture_ != 0) glDeleteTextures(1, &texture_);
        if (buffer_ != 0) glDeleteBuffers(1, &buffer_);
        buffer_ = std::exchange(other.buffer_, 0);
        texture_ = std::exchange(other.texture_, 0);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

void TextureBuffer::update(std::span<const glm::vec4> texels) {
    const auto bytes = static_cast<GLsizeiptr>(texels.size_bytes());
    glBindBuffer(GL_TEXTURE_BUFFER, buffer_);
    if (texels.size() == size_ && !texels.empty()) {
        glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes, texels.data());
    } else {
        // An empty buffer texture is legal but some drivers dislike a zero-sized store: keep one texel.
        const glm::vec4 none(0.0f);
        glBufferData(GL_TEXTURE_BUFFER, texels.empty() ? GLsizeiptr{sizeof none} : bytes,
                     texels.empty() ? &none : texels.data(), GL_DYNAMIC_DRAW);
        glBindTexture(GL_TEXTURE_BUFFER, texture_);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer_);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        size_ = texels.size();
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void TextureBuffer::bind(GLuint unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
}

} // namespace radiant::render::gl
