#pragma once
// A small RGBA8 texture the UI shows with ImGui::Image (the hemisphere's disk views) and the 3D
// hemisphere overlay samples: a gl::Texture2D that owns the GL name, plus uploads from memory.
// Create, upload and destroy on the thread whose GL context is current.
#include <cstdint>
#include <optional>
#include <span>

#include "render/gl/Texture.h"

namespace radiant::render {

class ImageTexture {
public:
    /// Replaces the contents: width * height * 4 bytes, top row first (as the UI draws it). Throws
    /// RadiantError when the byte count does not match.
    void upload(int width, int height, std::span<const std::uint8_t> rgba);
    /// The GL texture name, for ImGui::Image; 0 before the first upload.
    [[nodiscard]] unsigned int id() const { return texture_ ? texture_->id() : 0; }
    [[nodiscard]] int width() const { return texture_ ? texture_->width() : 0; }
    [[nodiscard]] int height() const { return texture_ ? texture_->height() : 0; }
    /// Binds it to texture unit `unit` (after an upload).
    void bind(unsigned int unit) const;

private:
    std::optional<gl::Texture2D> texture_;
};

} // namespace radiant::render
