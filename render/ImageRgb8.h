#pragma once
// An 8-bit RGB image in memory, top row first (as image files store it, unlike glReadPixels).
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace radiant::render {

struct ImageRgb8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  ///< width * height * 3 bytes, row-major, top row first

    [[nodiscard]] glm::u8vec3 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        return {pixels[i], pixels[i + 1], pixels[i + 2]};
    }
};

} // namespace radiant::render
