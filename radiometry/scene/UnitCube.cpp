#include "radiometry/scene/BoxScenes.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

Scene makeUnitCube() {
    Scene scene;
    scene.name = "unit-cube";
    scene.materials = {{"grey", Rgb{0.5}, ExitanceRgb{}}, {"light", Rgb{0.5}, ExitanceRgb{Rgb{1.0}}}};
    detail::addInwardBox(scene, {1, 1, 1}, "built-in unit-cube");
    scene.surfaces[scene.findSurface("ceiling")].material = 1;
    return scene;
}

} // namespace radiant
