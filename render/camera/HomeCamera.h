#pragma once
// The camera a scene opens with: the one home view (radiometry/scene/View.h: the Cornell camera for
// the Cornell box, a three-quarter framing of the bounds for anything else) as a render camera.
// The lab, `radiant render` and the importance solver's default all start from it. GL-free.
#include "radiometry/scene/Scene.h"
#include "radiometry/geometry/RayCaster.h"
#include "render/camera/Camera.h"

namespace radiant::render {

/// cameraFromView(homeView(scene, rays)): `rays` the scene's caster, or null to build one if needed.
Camera homeCamera(const Scene& scene, const RayCaster* rays = nullptr);

} // namespace radiant::render
