#pragma once
// Move-only owner of a 2D texture (render targets, later the false-colour legend's ramp).
#include <epoxy/gl.h>

#include <glm/vec4.hpp>
#include <span>

namespace radiant::render::gl {

class Texture2D {
public:
    /// Allocates width x height texels of `internalFormat` (GL_RGBA8, GL_RGBA16F, ...), linear filtering.
    Texture2D(int width, int height, GLenum internalFormat);
    ~Texture2D();
    Texture2D(Texture2D&& other) noexcept;
    Texture2D& operator=(Texture2D&& other) noexcept;
    Texture2D(const Texture2D&) = delete;
    Texture2D& operator=(const Texture2D&) = delete;

    [[nodiscard]] GLuint id() const { return id_; }
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    void bind(GLuint unit) const;
    /// Replaces every texel with `texels` (width x height, row-major from the bottom row, RGBA floats
    /// converted to the internal format); a size mismatch is an InvariantError. Restores the active
    /// unit's GL_TEXTURE_2D binding.
    void upload(std::span<const glm::vec4> texels);

private:
    GLuint id_ = 0;
    int width_ = 0;
    int height_ = 0;
};

} // namespace radiant::render::gl
