#pragma once
// The view a scene opens with: the Cornell camera for the Cornell box (its published camera), a
// three-quarter framing of the bounds for anything else. GL-free.
#include "radiometry/scene/Scene.h"
#include "render/camera/Camera.h"

namespace radiant::render {

/// Axis-aligned bounds of every face vertex (m); lo > hi for an empty scene.
void sceneBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi);

Camera homeCamera(const Scene& scene);

} // namespace radiant::render
