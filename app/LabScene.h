#pragma once
// What the lab does with a scene it opens, shared by the lab and the lesson stage: load it (warnings
// on stderr), and place the orbit camera at its home view.
#include <memory>
#include <string>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/Scene.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {

/// Loads a built-in name or a glTF path; throws RadiantError as loadScene does.
std::shared_ptr<const Scene> openScene(const std::string& nameOrPath);
/// The scene's one home camera (render/camera/HomeCamera.h), orbiting the centre of its bounds;
/// `rays` is the scene's one caster (the snapshot's), which the choice between an inside and an
/// outside view casts with. Without it, the outside framing (the first frame, before it exists).
render::OrbitCamera orbitFromHome(const Scene& scene, const RayCaster* rays);

} // namespace radiant::app
