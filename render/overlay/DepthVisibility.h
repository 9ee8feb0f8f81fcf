#pragma once
// Is a world point hidden behind what the 3D view drew? For markers drawn over the view (the
// probe's pick): the point's distance along the view axis against the depth buffer's at its pixel.
// GL-free header.
#include <glm/vec3.hpp>

#include "render/camera/Camera.h"

namespace radiant::render {

/// True when `world` is in front of, or on, the surface whose window depth `bufferDepth` (in
/// [0, 1]) the depth buffer holds at the point's pixel. Compared as distances along the view axis,
/// with a tolerance of 1% of the point's distance: the point lies on a surface that was drawn
/// pushed back by a polygon offset, and depth varies within a pixel on a slanted surface.
bool inFrontOfDepth(const Camera& camera, const Viewport& viewport, const glm::dvec3& world, double bufferDepth);

/// inFrontOfDepth against the bound framebuffer's depth at the point's pixel, read back (one value:
/// waits for the drawing so far, so call it at most once a frame). False off screen and behind the eye.
bool visibleInDepthBuffer(const Camera& camera, const Viewport& viewport, int framebufferHeight, const glm::dvec3& world);

} // namespace radiant::render
