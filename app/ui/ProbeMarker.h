#pragma once
// The probe's cross-hair over the 3D view: a ring with four ticks at the picked point, hidden where
// the scene stands in front of it (read from the depth buffer). Main thread, between the scene's
// drawing and the UI pass.
#include <glm/vec3.hpp>

#include "render/camera/Camera.h"

namespace radiant::app {

/// `viewport` in framebuffer pixels (top-left origin), as the scene was drawn into it;
/// `pixelRatio` framebuffer pixels per UI unit.
void drawProbeMarker(const render::Camera& camera, const render::Viewport& viewport, int framebufferHeight,
                     float pixelRatio, const glm::dvec3& point);

} // namespace radiant::app
