#include "render/Screenshot.h"

#include <ctime>

#include "radiometry/common/Error.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
// Through its folder: render/ does not get the stb pkg-config include path (imgui brings it to app/ only).
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace radiant::render {

void writePng(const ImageRgb8& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
        throw RadiantError({path.string(), "png"}, "image of " + std::to_string(image.width) + " x " +
                                                       std::to_string(image.height) + " pixels holds " +
                                                       std::to_string(image.pixels.size()) + " bytes");
    if (stbi_write_png(path.string().c_str(), image.width, image.height, 3, image.pixels.data(), image.width * 3) == 0)
        throw RadiantError({path.string(), "png"}, "cannot write the PNG file (directory missing or not writable?)");
}

std::string screenshotFileName(std::chrono::system_clock::time_point when) {
    const std::time_t seconds = std::chrono::system_clock::to_time_t(when);
    std::tm local{};
    localtime_r(&seconds, &local);
    char name[64];
    std::strftime(name, sizeof name, "radiant-%Y%m%d-%H%M%S.png", &local);
    return name;
}

std::filesystem::path saveScreenshot(const ImageRgb8& image, const std::filesystem::path& directory) {
    const std::string name = screenshotFileName(std::chrono::system_clock::now());
    std::filesystem::path path = directory / name;
    for (int copy = 2; std::filesystem::exists(path); ++copy)
        path = directory / (name.substr(0, name.size() - 4) + "-" + std::to_string(copy) + ".png");
    writePng(image, path);
    return path;
}

} // namespace radiant::render
