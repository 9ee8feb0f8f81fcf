#pragma once
// Pinhole camera math, GL-free (glm only): the lab, the offscreen renderer and the GL tests all
// project with these functions, so a test's expected pixel comes from the same conventions.
// Right-handed world, camera looks down its forward axis; OpenGL clip space.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "radiometry/scene/View.h"
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

/// The camera of a view (radiometry/scene/View.h), its depth range set from the eye's distance to
/// the target: near 1/1000 of it (at least 0.1 mm), far 100 times it, room to zoom out.
Camera cameraFromView(const View& view);
/// What the camera shows in a viewport of this aspect (width / height), as the importance solver
/// takes it: target one metre ahead, the vertical field of that aspect.
View viewFromCamera(const Camera& camera, double aspect);

/// cameraFromView(cornellView()).
Camera cornellCamera();
/// cameraFromView(framingView(lo, hi)).
Camera framingCamera(const glm::dvec3& lo, const glm::dvec3& hi);

/// Where a world point lands in the viewport, in framebuffer pixels from the top-left; z is the
/// window depth in [0, 1]. Points behind the eye give meaningless x, y (check depth).
glm::dvec3 projectToPixel(const Camera& camera, const Viewport& viewport, const glm::dvec3& world);

} // namespace radiant::render
