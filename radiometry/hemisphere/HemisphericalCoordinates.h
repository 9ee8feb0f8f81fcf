#pragma once
// Directions over the hemisphere above a surface point, as the lecture parametrises them: polar
// angle theta from the normal in [0, pi/2], azimuth phi in [0, 2 pi), and the measure
// d omega = sin(theta) d theta d phi. The tangent frame follows Duff et al., "Building an
// Orthonormal Basis, Revisited" (JCGT 2017): continuous everywhere except the normal's -z pole.
#include <glm/vec3.hpp>

#include "radiometry/units/Angle.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

struct SphericalDirection {
    Radians theta;  ///< polar angle from the normal
    Radians phi;    ///< azimuth from the frame's tangent, in [0, 2 pi)
};

/// An orthonormal frame (tangent, bitangent, normal) about a surface normal; local z is the normal.
class HemisphereFrame {
public:
    /// The frame of the world axes: local coordinates are world coordinates.
    HemisphereFrame() = default;
    /// Throws RadiantError when the normal is zero or not finite; normalises it otherwise.
    explicit HemisphereFrame(const glm::dvec3& normal);

    [[nodiscard]] const glm::dvec3& tangent() const { return tangent_; }
    [[nodiscard]] const glm::dvec3& bitangent() const { return bitangent_; }
    [[nodiscard]] const glm::dvec3& normal() const { return normal_; }

    [[nodiscard]] glm::dvec3 toWorld(const glm::dvec3& local) const;
    [[nodiscard]] glm::dvec3 toLocal(const glm::dvec3& world) const;
    /// The same normal with tangent and bitangent turned by `angle` about it (counter-clockwise
    /// seen from above), e.g. to take a hemicube's pixel rows off a room's axes.
    [[nodiscard]] HemisphereFrame turned(Radians angle) const;

private:
    glm::dvec3 tangent_{1, 0, 0};
    glm::dvec3 bitangent_{0, 1, 0};
    glm::dvec3 normal_{0, 0, 1};
};

/// Unit direction in the frame's local coordinates (z along the normal).
glm::dvec3 localDirection(SphericalDirection angles);
/// Unit world direction at (theta, phi) about the frame's normal.
glm::dvec3 directionFromAngles(const HemisphereFrame& frame, SphericalDirection angles);
/// (theta, phi) of a world direction (need not be unit; must not be zero) about the frame's normal.
/// theta lies in [0, pi]: directions below the surface have theta > pi/2.
SphericalDirection anglesFromDirection(const HemisphereFrame& frame, const glm::dvec3& direction);

/// d omega = sin(theta) d theta d phi: the solid angle of a small (d theta x d phi) cell at theta.
SolidAngle differentialSolidAngle(Radians theta, Radians dTheta, Radians dPhi);

} // namespace radiant
