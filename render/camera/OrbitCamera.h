#pragma once
// The lab's interactive camera: orbits a pivot (the scene's centre), pans the pivot, zooms by distance.
// GL-free so its motions are unit-testable.
#include <glm/vec3.hpp>

#include "render/camera/Camera.h"

namespace radiant::render {

class OrbitCamera {
public:
    /// Starts at `home`, pivoting about the point on its line of sight nearest `centre`.
    OrbitCamera(const Camera& home, const glm::dvec3& centre);

    [[nodiscard]] Camera camera() const;
    [[nodiscard]] const glm::dvec3& pivot() const { return pivot_; }
    [[nodiscard]] double distance() const { return distance_; }

    /// Turns about the pivot: yaw about +y, pitch about the camera's right axis (clamped short of the poles).
    void orbit(Radians yaw, Radians pitch);
    /// Moves the pivot in the view plane by a fraction of the viewport height, so a dragged point
    /// on the pivot's depth stays under the cursor.
    void pan(double rightFraction, double upFraction);
    /// Each step moves 15% closer (positive) or further (negative).
    void zoom(double steps);
    /// Back to the home view.
    void reset();

private:
    [[nodiscard]] glm::dvec3 forward() const;

    Camera home_;
    glm::dvec3 homePivot_;
    double homeDistance_;
    double homeYaw_, homePitch_;
    glm::dvec3 pivot_;
    double distance_;
    double yaw_;    ///< radians; 0 looks along +z
    double pitch_;  ///< radians; positive looks up
};

} // namespace radiant::render
