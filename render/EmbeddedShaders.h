#pragma once
// GLSL sources from shaders/, compiled into the binary by cmake/EmbedShaders.cmake.
#include <optional>
#include <string_view>

namespace radiant::render {

/// The text of shaders/<fileName>, or nullopt when no such file was embedded.
std::optional<std::string_view> embeddedShader(std::string_view fileName);

} // namespace radiant::render
