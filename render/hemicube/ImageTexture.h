#pragma once
// A small RGBA8 texture the UI shows with ImGui::Image (the hemisphere's disk views). GL-free header;
// create, upload and destroy on the thread whose GL context is current.
#include <cstdint>
#include <span>

namespace radiant::render {

class ImageTexture {
public:
    ImageTexture();
    ~ImageTexture();
    ImageTexture(ImageTexture&& other) noexcept;
    ImageTexture& operator=(ImageTexture&& other) noexcept;
    ImageTexture(const ImageTexture&) = delete;
    ImageTexture& operator=(const ImageTexture&) = delete;

    /// Replaces the contents: width * height * 4 bytes, top row first (as the UI draws it).
    void upload(int width, int height, std::span<const std::uint8_t> rgba);
    /// The GL texture name, for ImGui::Image.
    [[nodiscard]] unsigned int id() const { return id_; }
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }

private:
    unsigned int id_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace radiant::render
