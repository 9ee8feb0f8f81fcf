#pragma once
// The frame a hemicube is rendered in: HemisphereFrame(normal) turned about the normal by a fixed
// twist. Rooms are built of axis-aligned rectangles, and so is an untwisted hemicube about an axis
// normal: a light's edge then runs along a pixel row, the whole row falls in or out together, and
// the form factor jumps by a row's worth (the Cornell light read 3-4 % off at 256 px, 5 % at 128).
// Turned by pi/8 the edges cross the rows and the per-pixel errors average out (0.2 % at 256 px).
// Turning the hemicube about the normal is the radiosity literature's remedy for this aliasing
// (M. F. Cohen and J. R. Wallace, "Radiosity and Realistic Image Synthesis", 1993, turn it at random
// per patch); a fixed twist keeps the picture steady from frame to frame. GL-free.
#include <numbers>

#include <glm/vec3.hpp>

#include "radiometry/hemisphere/HemisphericalCoordinates.h"

namespace radiant::render {

inline constexpr double kHemicubeTwist = std::numbers::pi / 8;  ///< radians about the normal

class HemicubeFrame : public HemisphereFrame {
public:
    /// Throws RadiantError for a zero or non-finite normal (as HemisphereFrame does). Local
    /// coordinates: z along the normal, x along the twisted tangent (HemicubeLayout's frame).
    explicit HemicubeFrame(const glm::dvec3& normal, double twist = kHemicubeTwist)
        : HemisphereFrame(HemisphereFrame(normal).turned(Radians(twist))) {}
};

} // namespace radiant::render
