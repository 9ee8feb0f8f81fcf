#pragma once
// Move-only offscreen render target: an RGBA8 colour texture and a depth renderbuffer, for captures
// and `radiant render` at any size, independent of the window.
#include <epoxy/gl.h>

#include "render/ImageRgb8.h"
#include "render/gl/Texture.h"

namespace radiant::render::gl {

class Framebuffer {
public:
    /// Throws RadiantError when the driver reports the attachment combination incomplete.
    Framebuffer(int width, int height);
    ~Framebuffer();
    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    [[nodiscard]] GLuint id() const { return id_; }
    [[nodiscard]] int width() const { return colour_.width(); }
    [[nodiscard]] int height() const { return colour_.height(); }
    [[nodiscard]] const Texture2D& colour() const { return colour_; }

    /// Binds it for drawing and sets the viewport to cover it.
    void bindForDrawing() const;
    [[nodiscard]] ImageRgb8 readRgb8() const;

private:
    Texture2D colour_;
    GLuint depth_ = 0;
    GLuint id_ = 0;
};

/// Reads the given rectangle of a framebuffer's colour buffer (0 = the window's back buffer),
/// flipped so the top row comes first.
ImageRgb8 readPixelsRgb8(GLuint framebuffer, int x, int y, int width, int height);

} // namespace radiant::render::gl
