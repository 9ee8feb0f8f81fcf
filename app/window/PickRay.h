#pragma once
// The ray from the camera through one pixel of the 3D view: what a click on the scene picks.
// GL-free (glm only), the inverse of render::projectToPixel.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera/Camera.h"

namespace radiant::app {

struct PickRay {
    glm::dvec3 origin{0.0};     ///< on the near plane, metres
    glm::dvec3 direction{0.0};  ///< unit
};

/// `pixel` in framebuffer pixels from the window's top-left, as projectToPixel returns them; the
/// ray passes through the pixel's position exactly (pass x + 0.5 for a pixel's centre).
PickRay pickRay(const render::Camera& camera, const render::Viewport& viewport, const glm::dvec2& pixel);

} // namespace radiant::app
