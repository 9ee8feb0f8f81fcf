#include "render/gl/Texture.h"

#include <cstddef>
#include <utility>

#include "radiometry/common/Check.h"
#include "render/gl/ScopedBinding.h"

namespace radiant::render::gl {

Texture2D::Texture2D(int width, int height, GLenum internalFormat) : width_(width), height_(height) {
    glGenTextures(1, &id_);
    const ScopedTexture2D bound(id_);
    // Immutable storage is 4.2+; TexImage keeps the 3.3 fallback working. Format/type only describe
    // the (absent) upload, so any pair valid for the internal format will do.
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Texture2D::~Texture2D() {
    if (id_ != 0) glDeleteTextures(1, &id_);
}

Texture2D::Texture2D(Texture2D&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_) {}

Texture2D& Texture2D::operator=(Texture2D&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) glDeleteTextures(1, &id_);
        id_ = std::exchange(other.id_, 0);
        width_ = other.width_;
        height_ = other.height_;
    }
    return *this;
}

void Texture2D::bind(GLuint unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, id_);
}

} // namespace radiant::render::gl

namespace radiant::render::gl {

void Texture2D::upload(std::span<const glm::vec4> texels) {
    RADIANT_CHECK_EQ(texels.size(), static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    const ScopedTexture2D bound(id_);
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
}

} // namespace radiant::render::gl
