#pragma once
// Where the reference path tracer estimates: a point on one face of the scene, facing that face's
// front. Found from the scene's own polygons (no patch mesh), so a point the user names is checked
// by the same geometry the rays see.
#include <cstdint>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct ReferencePoint {
    std::uint32_t surface = 0;
    std::uint32_t face = 0;
    glm::dvec3 point{0.0};       ///< on the face's plane (projected there), metres
    glm::dvec3 normal{0, 0, 1};  ///< the face's own unit normal: B = M + rho E holds facing it
};

/// How close a point must be, and how closely a normal must agree with the face's.
struct ReferencePointTolerance {
    double distance = 1e-4;      ///< off the face, relative to the scene's bounding-box diagonal
    double angleDegrees = 5.0;   ///< between the given normal and the face's
};

/// The face whose polygon contains x (within the tolerance) and whose normal agrees best with n.
/// Throws RadiantError (element "--point" or "--normal") naming the values when x lies on no face,
/// when n is not a finite non-zero vector, or when n is further than the tolerance from the face's
/// normal (the reference reads a surface's radiosity, which faces the surface's front only).
[[nodiscard]] ReferencePoint locateReferencePoint(const Scene& scene, const glm::dvec3& x, const glm::dvec3& n,
                                                  const ReferencePointTolerance& tolerance = {});

} // namespace radiant
