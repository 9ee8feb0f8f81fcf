#pragma once
// Next-event estimation's source of light: a point drawn on the scene's emitting faces with density
// proportional to their exitance (summed over bands), so bright emitters get the samples. Faces are
// fan-triangulated (they are convex) and a point is uniform on its triangle (Shirley's square-root
// warp), which keeps the density constant over each face.
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"

namespace radiant::reference {

struct EmitterSample {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 0, 1};  ///< the emitting (front) side
    Rgb exitance{0.0};           ///< W/m^2
    double inverseDensity = 0;   ///< 1 / p(y), m^2: the area measure's density at the point
};

class EmitterSampler {
public:
    explicit EmitterSampler(const Scene& scene);

    [[nodiscard]] bool empty() const { return triangles_.empty(); }
    /// A point for three uniform numbers in [0, 1). Precondition: !empty().
    [[nodiscard]] EmitterSample sample(double chooseTriangle, double u, double v) const;
    /// The density (1/m^2) with which sample() draws a point on an emitter of this exitance.
    [[nodiscard]] double density(const Rgb& exitance) const {
        return totalWeight_ > 0 ? (exitance.x + exitance.y + exitance.z) / totalWeight_ : 0.0;
    }

private:
    struct Triangle {
        glm::dvec3 a, b, c, normal;
        Rgb exitance;
    };
    std::vector<Triangle> triangles_;
    std::vector<double> cumulativeWeight_;  ///< running sum of area x (M_r + M_g + M_b)
    double totalWeight_ = 0;                ///< W/m^2 x m^2: the emitted power summed over bands
};

} // namespace radiant::reference
