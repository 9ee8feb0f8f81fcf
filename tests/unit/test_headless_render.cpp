// `radiant render` with no X server: the binary runs with DISPLAY unset, so only the headless EGL
// context can draw, and the PNG it writes must be the requested size and show the lit box.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "render/display/LegendImage.h"

namespace {

std::string runCommand(const std::string& command, int& exitStatus) {
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string output;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe)) output += chunk.data();
    const int status = pclose(pipe);
    exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return output;
}

} // namespace

TEST_CASE("radiant render draws the Cornell box with DISPLAY unset (headless EGL)") {
    const std::filesystem::path png = std::filesystem::temp_directory_path() / "radiant_headless_render.png";
    std::filesystem::remove(png);
    // A small picture of a coarse mesh: the point is the context, not the solve.
    const std::string command = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + RADIANT_BINARY +
                                "' render cornell-box --max-patch-area 0.02 --width 160 --height 100 --png '" +
                                png.string() + "' 2>&1";
    int status = -1;
    const std::string output = runCommand(command, status);
    INFO(output);
    REQUIRE(status == 0);
    REQUIRE(std::filesystem::exists(png));

    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.string().c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels != nullptr);
    CHECK(width == 160);
    CHECK(height == 100);
    // Not blank: the background is a dark grey (about 0.08 sRGB, 20 of 255); the lit walls and the
    // lamp are far brighter, and the red and green walls differ in hue.
    int bright = 0, reddish = 0, greenish = 0;
    for (int i = 0; i < width * height; ++i) {
        const int r = pixels[3 * i], g = pixels[3 * i + 1], b = pixels[3 * i + 2];
        if (r + g + b > 3 * 100) ++bright;
        if (r > g + 40 && r > b + 40) ++reddish;
        if (g > r + 40 && g > b + 40) ++greenish;
    }
    stbi_image_free(pixels);
    std::filesystem::remove(png);
    const int total = width * height;
    CHECK(bright > total / 10);
    CHECK(reddish > total / 50);
    CHECK(greenish > total / 50);
}

TEST_CASE("radiant render --false-colour puts the legend in the picture: a viridis bar in the top-right corner") {
    const std::filesystem::path png = std::filesystem::temp_directory_path() / "radiant_headless_legend.png";
    std::filesystem::remove(png);
    const std::string command = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + RADIANT_BINARY +
                                "' render cornell-box --max-patch-area 0.02 --width 640 --height 400 --false-colour "
                                "--log-scale --png '" + png.string() + "' 2>&1";
    int status = -1;
    const std::string output = runCommand(command, status);
    INFO(output);
    REQUIRE(status == 0);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.string().c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels != nullptr);
    // Where render::layoutLegend puts the bar for this size: viridis' top colour (253, 231, 37) in its
    // first row, its bottom one (68, 1, 84) in its last, in a picture whose scene is not there.
    const radiant::render::ColourLegend legend = radiant::render::makeLegend(1.0, true, 3);
    const radiant::render::LegendLayout l = radiant::render::layoutLegend(legend, width, height);
    const auto at = [&](int x, int y) {
        const unsigned char* p = pixels + 3 * (y * width + x);
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    const int x = (l.barLeft + l.barRight) / 2;
    const std::array<int, 3> top = at(x, l.barTop), bottom = at(x, l.barBottom - 1);
    INFO("top " << top[0] << "," << top[1] << "," << top[2] << "; bottom " << bottom[0] << "," << bottom[1] << "," << bottom[2]);
    CHECK(std::abs(top[0] - 253) <= 2);
    CHECK(std::abs(top[1] - 231) <= 2);
    CHECK(std::abs(top[2] - 37) <= 2);
    CHECK(std::abs(bottom[0] - 68) <= 2);
    CHECK(std::abs(bottom[1] - 1) <= 2);
    CHECK(std::abs(bottom[2] - 84) <= 2);
    CHECK(l.barLeft > width / 2);
    stbi_image_free(pixels);
    std::filesystem::remove(png);
}
