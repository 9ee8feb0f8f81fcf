#pragma once
// A pinhole view of a scene, GL-free: what importance-driven radiosity's camera emits importance
// through, and the one home view every scene opens with (the lab, `radiant render`, the
// importance solver's default), so that they all look at the same thing.
#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant {

class RayCaster;

struct View {
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0, 0, 1};
    glm::dvec3 up{0, 1, 0};
    double verticalFov = 0.7;  ///< radians, of the image's height
    double aspect = 1.0;       ///< image width / height
};

/// The Cornell Program of Computer Graphics' camera (docs/reference.md): eye (0.278, 0.273, -0.8) m
/// looking along +z, up +y, a 35 mm lens on 25 mm film: field of view 2 atan(12.5 / 35).
View cornellView();

/// Three-quarters down onto the box [lo, hi] (mostly along +z, up +y), far enough that its
/// bounding sphere fits the field of view, aimed at its centre: a head-on view of a box shows one
/// flat square.
View framingView(const glm::dvec3& lo, const glm::dvec3& hi);

/// Axis-aligned bounds of every face vertex (m); false (and lo > hi) for a scene without one.
bool sceneBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi);

/// The view a scene opens with: the Cornell camera for the Cornell box (its published camera), the
/// scene's first glTF camera where it has one,
/// framingView of the bounds for anything else, or a wide view from inside the bounds when that
/// sees more front faces (a closed room or furnace from outside shows only its walls' backs; two
/// plates facing each other mostly theirs).
/// Casts a few hundred rays.
/// `rays`: the scene's ray caster when the caller has one; null builds one when the rule needs it.
View homeView(const Scene& scene, const RayCaster* rays = nullptr);
/// The same without casting a ray: the outside framing where homeView would choose between inside
/// and outside. For a window's first frame, before the scene's one ray caster exists.
View homeViewWithoutRays(const Scene& scene);

} // namespace radiant
