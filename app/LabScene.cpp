#include "app/LabScene.h"

#include <cstdio>

#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/scene/View.h"
#include "render/camera/HomeCamera.h"

namespace radiant::app {

std::shared_ptr<const Scene> openScene(const std::string& nameOrPath) {
    LoadedScene loaded = loadScene(nameOrPath);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
    return std::make_shared<const Scene>(std::move(loaded.scene));
}

render::OrbitCamera orbitFromHome(const Scene& scene, const RayCaster* rays) {
    glm::dvec3 lo, hi;
    const render::Camera home = rays ? render::homeCamera(scene, rays) : render::cameraFromView(homeViewWithoutRays(scene));
    if (!sceneBounds(scene, lo, hi)) return render::OrbitCamera(home, home.eye + home.forward);
    return render::OrbitCamera(home, (lo + hi) / 2.0);
}


} // namespace radiant::app
