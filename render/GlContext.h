#pragma once
// The few whole-frame GL operations the app needs, behind a GL-free header so app/ never sees GL.
// Call on the thread whose context is current.
#include <glm/vec3.hpp>
#include <string>

#include "render/ImageRgb8.h"
#include "render/camera/Camera.h"

namespace radiant::render {

struct GlInfo {
    std::string renderer;  ///< GL_RENDERER
    std::string version;   ///< GL_VERSION
    std::string vendor;    ///< GL_VENDOR
    int major = 0;         ///< context version actually created
    int minor = 0;
};

GlInfo queryGlInfo();

/// Clears the whole window framebuffer (size in pixels) to `background` (sRGB-encoded, as the
/// display shows it) and restricts drawing to `sceneViewport` (top-left origin).
void beginWindowFrame(int framebufferWidth, int framebufferHeight, const Viewport& sceneViewport,
                      const glm::vec3& background);

/// Restricts drawing to `viewport` (top-left origin) of the window's framebuffer: one half of a split
/// 3D view (the comparison mode draws two solutions with one camera, side by side).
void useViewport(int framebufferHeight, const Viewport& viewport);

/// Resets the viewport to the whole window, for the UI pass.
void useWholeWindow(int framebufferWidth, int framebufferHeight);

/// Reads the window's back buffer (what the next swap will show), top row first.
ImageRgb8 readWindowPixels(int framebufferWidth, int framebufferHeight);

} // namespace radiant::render
