#include "render/hemicube/ImageTexture.h"

#include <epoxy/gl.h>

#include <string>

#include "radiometry/common/Error.h"

namespace radiant::render {

void ImageTexture::upload(int width, int height, std::span<const std::uint8_t> rgba) {
    if (width <= 0 || height <= 0 ||
        rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
        throw RadiantError({"", "image texture"}, std::to_string(rgba.size()) + " bytes for " + std::to_string(width) +
                                                      " x " + std::to_string(height) + " RGBA pixels");
    if (!texture_ || texture_->width() != width || texture_->height() != height) {
        texture_.emplace(width, height, GL_RGBA8);
        glBindTexture(GL_TEXTURE_2D, texture_->id());
        // Magnified without smoothing: a teaching view shows the hemicube's pixels as they are.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, texture_->id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

void ImageTexture::bind(unsigned int unit) const {
    if (texture_) texture_->bind(unit);
}

} // namespace radiant::render
