#pragma once
// PNG files from captured frames (F12 in the lab, `radiant render`). GL-free header.
#include <chrono>
#include <filesystem>
#include <string>

#include "render/ImageRgb8.h"

namespace radiant::render {

/// Writes the image as an 8-bit RGB PNG; throws RadiantError naming the path when it cannot.
void writePng(const ImageRgb8& image, const std::filesystem::path& path);

/// "radiant-YYYYMMDD-HHMMSS.png" in local time.
std::string screenshotFileName(std::chrono::system_clock::time_point when);

/// Writes the image to `directory`/radiant-YYYYMMDD-HHMMSS.png (now) and returns that path, for a
/// status line. A second shot within the same second gets "-2", "-3", ... rather than overwriting.
std::filesystem::path saveScreenshot(const ImageRgb8& image, const std::filesystem::path& directory = ".");

} // namespace radiant::render
