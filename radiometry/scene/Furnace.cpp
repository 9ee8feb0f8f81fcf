#include "radiometry/scene/BoxScenes.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

Scene makeFurnace() {
    Scene scene;
    scene.name = "furnace";
    // Not a cube, so that a solver passing only because of symmetry is caught.
    scene.materials = {{"furnace wall", Rgb{0.5}, ExitanceRgb{Rgb{1.0}}}};
    detail::addInwardBox(scene, {2.0, 1.0, 1.5}, "built-in furnace");
    return scene;
}

} // namespace radiant
