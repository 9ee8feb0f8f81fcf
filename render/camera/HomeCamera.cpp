#include "render/camera/HomeCamera.h"

#include "radiometry/scene/View.h"

namespace radiant::render {

Camera homeCamera(const Scene& scene, const RayCaster* rays) { return cameraFromView(homeView(scene, rays)); }

} // namespace radiant::render
