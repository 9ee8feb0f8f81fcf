#pragma once
// Pinhole camera math, GL-free (glm only): the lab, the offscreen renderer and the GL tests all
// project with these functions, so a test's expected pixel comes from the same conventions.
// Right-handed world, camera looks down its forward axis; OpenGL clip space.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "radiometry/units/Angle.h"

namespace radiant::render {

/// A rectangle of the framebuffer in pixels, origin at the top-left (as windows and images count).
struct Viewport {
    int x = 0;
    int y = 0;
    int width = 1;
    int height = 1;
    [[nodiscard]] double aspect() const { return static_cast<double>(width) / static_cast<double>(height); }
};

struct Camera {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0, 0, 1};  ///< unit
    glm::dvec3 up{0, 1, 0};
    /// Vertical field of view for landscape viewports. Portrait viewports keep this as the
    /// horizontal field instead, so what the camera frames always fits.
    Radians fieldOfView{0.7};
    double nearPlane = 0.01;  ///< m
    double farPlane = 100.0;  ///< m

    [[nodiscard]] glm::dmat4 view() const;
    [[nodiscard]] glm::dmat4 projection(double aspect) const;
    [[nodiscard]] Radians verticalFieldOfView(double aspect) const;
    [[nodiscard]] glm::dmat4 viewProjection(double aspect) const { return projection(aspect) * view(); }
};

/// The Cornell Program of Computer Graphics' camera (oracles.md): eye (0.278, 0.273, -0.8) m looking
/// along +z, up +y, a 35 mm lens on 25 mm film: field of view 2 atan(12.5 / 35).
Camera cornellCamera();

/// A camera looking three-quarters down onto the box [lo, hi] (mostly along +z, up +y), far enough that its
/// bounding sphere fits the field of view: the home view of scenes without a published camera.
Camera framingCamera(const glm::dvec3& lo, const glm::dvec3& hi);

/// Where a world point lands in the viewport, in framebuffer pixels from the top-left; z is the
/// window depth in [0, 1]. Points behind the eye give meaningless x, y (check depth).
glm::dvec3 projectToPixel(const Camera& camera, const Viewport& viewport, const glm::dvec3& world);

} // namespace radiant::render
