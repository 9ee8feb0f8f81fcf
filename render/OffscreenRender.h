#pragma once
// Draws a scene renderer into an offscreen framebuffer of any size and reads it back: captures that
// do not depend on the window's size, and `radiant render`. Needs a current GL context. GL-free header.
#include <glm/vec3.hpp>

#include "render/ImageRgb8.h"
#include "render/SceneRenderer.h"
#include "render/camera/Camera.h"

namespace radiant::render {

/// `background` is sRGB-encoded, as the display shows it. Leaves the window framebuffer bound.
ImageRgb8 renderOffscreen(const SceneRenderer& renderer, const Camera& camera, int width, int height,
                          const glm::vec3& background);

} // namespace radiant::render
