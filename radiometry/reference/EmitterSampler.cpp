#include "radiometry/reference/EmitterSampler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace radiant::reference {

EmitterSampler::EmitterSampler(const Scene& scene) {
    for (const Surface& surface : scene.surfaces) {
        const Material& material = scene.materials.at(surface.material);
        if (!material.emits()) continue;
        const Rgb exitance = material.exitance.value();
        const double bandSum = exitance.x + exitance.y + exitance.z;
        for (const Face& face : surface.faces)
            for (std::size_t k = 1; k + 1 < face.vertices.size(); ++k) {
                const glm::dvec3 &a = face.vertices[0], &b = face.vertices[k], &c = face.vertices[k + 1];
                const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
                if (!(area > 0)) continue;
                totalWeight_ += area * bandSum;
                triangles_.push_back({a, b, c, face.normal, exitance});
                cumulativeWeight_.push_back(totalWeight_);
            }
    }
}

EmitterSample EmitterSampler::sample(double chooseTriangle, double u, double v) const {
    const double target = chooseTriangle * totalWeight_;
    const auto found = std::upper_bound(cumulativeWeight_.begin(), cumulativeWeight_.end(), target);
    const std::size_t index =
        std::min<std::size_t>(static_cast<std::size_t>(found - cumulativeWeight_.begin()), triangles_.size() - 1);
    const Triangle& t = triangles_[index];
    const double su = std::sqrt(u);
    const double wa = 1 - su, wb = v * su;
    EmitterSample s;
    s.point = wa * t.a + wb * t.b + (1 - wa - wb) * t.c;
    s.normal = t.normal;
    s.exitance = t.exitance;
    // p(y) = (area x bandSum / total) / area: constant over every emitter of the same exitance.
    s.inverseDensity = totalWeight_ / (t.exitance.x + t.exitance.y + t.exitance.z);
    return s;
}

} // namespace radiant::reference
