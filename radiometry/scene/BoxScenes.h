#pragma once
// Shared by the built-in scenes made of axis-aligned rectangles.
#include <glm/vec3.hpp>
#include <string>

#include "radiometry/scene/Scene.h"

namespace radiant::detail {

/// A rectangle from a corner and two edge vectors; its normal is normalize(u x v).
inline Face rectangleFace(const glm::dvec3& corner, const glm::dvec3& u, const glm::dvec3& v) {
    Face face;
    face.vertices = {corner, corner + u, corner + u + v, corner + v};
    face.updateGeometry();
    return face;
}

/// The six inward-facing sides of the box [0, size]: floor, ceiling, wall -x, wall +x, wall -z,
/// wall +z, all with material 0 except where the caller changes them.
inline void addInwardBox(Scene& scene, const glm::dvec3& size, const std::string& origin) {
    const double x = size.x, y = size.y, z = size.z;
    const auto add = [&](std::string name, Face face) {
        scene.surfaces.push_back({std::move(name), 0, {std::move(face)}, origin});
    };
    add("floor", rectangleFace({0, 0, 0}, {0, 0, z}, {x, 0, 0}));      // normal +y
    add("ceiling", rectangleFace({0, y, 0}, {x, 0, 0}, {0, 0, z}));    // normal -y
    add("wall -x", rectangleFace({0, 0, 0}, {0, y, 0}, {0, 0, z}));    // normal +x
    add("wall +x", rectangleFace({x, 0, 0}, {0, 0, z}, {0, y, 0}));    // normal -x
    add("wall -z", rectangleFace({0, 0, 0}, {x, 0, 0}, {0, y, 0}));    // normal +z
    add("wall +z", rectangleFace({0, 0, z}, {0, y, 0}, {x, 0, 0}));    // normal -z
}

} // namespace radiant::detail
