#pragma once
// Scene faces as flat-shaded triangles for drawing (GL-free, so it is unit-testable): each convex
// face becomes a fan, each vertex carries its face's normal and its material's display colour.
#include <glm/vec3.hpp>
#include <vector>

#include "radiometry/scene/Scene.h"

namespace radiant::render {

struct FlatVertex {
    glm::vec3 position;  ///< m
    glm::vec3 normal;    ///< unit, the face's
    glm::vec3 colour;    ///< linear RGB in [0, 1]
    float emissive;      ///< 1 for emitters: drawn at their colour, without shading
};

/// The colour a material is drawn with before any solve: its reflectance, or for an emitter its
/// exitance's chromaticity scaled so the brightest band is 1.
glm::vec3 displayColour(const Material& material);

/// Three vertices per triangle, faces fan-triangulated about their first vertex.
std::vector<FlatVertex> flatTriangles(const Scene& scene);

} // namespace radiant::render
