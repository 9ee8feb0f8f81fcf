#include "render/camera/HomeCamera.h"

#include "radiometry/scene/View.h"

namespace radiant::render {

Camera homeCamera(const Scene& scene) { return cameraFromView(homeView(scene)); }

} // namespace radiant::render
