#include "render/gl/Framebuffer.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "radiometry/common/Error.h"

namespace radiant::render::gl {

Framebuffer::Framebuffer(int width, int height) : colour_(width, height, GL_RGBA8) {
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glGenFramebuffers(1, &id_);
    glBindFramebuffer(GL_FRAMEBUFFER, id_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &id_);
        glDeleteRenderbuffers(1, &depth_);
        char status_hex[16];
        std::snprintf(status_hex, sizeof status_hex, "0x%04x", status);
        throw RadiantError({"offscreen framebuffer", std::to_string(width) + " x " + std::to_string(height)},
                           std::string("incomplete, glCheckFramebufferStatus = ") + status_hex);
    }
}

Framebuffer::~Framebuffer() {
    if (id_ != 0) glDeleteFramebuffers(1, &id_);
    if (depth_ != 0) glDeleteRenderbuffers(1, &depth_);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : colour_(std::move(other.colour_)), depth_(std::exchange(other.depth_, 0)), id_(std::exchange(other.id_, 0)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) glDeleteFramebuffers(1, &id_);
        if (depth_ != 0) glDeleteRenderbuffers(1, &depth_);
        colour_ = std::move(other.colour_);
        depth_ = std::exchange(other.depth_, 0);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void Framebuffer::bindForDrawing() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id_);
    glViewport(0, 0, width(), height());
}

ImageRgb8 Framebuffer::readRgb8() const { return readPixelsRgb8(id_, 0, 0, width(), height()); }

ImageRgb8 readPixelsRgb8(GLuint framebuffer, int x, int y, int width, int height) {
    ImageRgb8 image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (framebuffer == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.pixels.data());
    // GL's rows run bottom-up.
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 3;
    for (int row = 0; row < height / 2; ++row)
        std::swap_ranges(image.pixels.begin() + static_cast<std::ptrdiff_t>(row * rowBytes),
                         image.pixels.begin() + static_cast<std::ptrdiff_t>((row + 1) * rowBytes),
                         image.pixels.begin() + static_cast<std::ptrdiff_t>((height - 1 - row) * rowBytes));
    return image;
}

} // namespace radiant::render::gl
