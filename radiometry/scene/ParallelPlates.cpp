#include "radiometry/scene/BoxScenes.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

Scene makeParallelPlates() {
    Scene scene;
    scene.name = "parallel-plates";
    // A black emitter keeps the two-patch answer simple: B_receiver = rho F E, B_emitter = E.
    scene.materials = {{"emitter", Rgb{0.0}, ExitanceRgb{Rgb{1.0}}}, {"receiver", Rgb{0.5}, ExitanceRgb{}}};
    const std::string origin = "built-in parallel-plates";
    scene.surfaces.push_back({"emitter", 0, {detail::rectangleFace({0, 0, 0}, {0, 0, 1}, {1, 0, 0})}, origin});
    scene.surfaces.push_back({"receiver", 1, {detail::rectangleFace({0, 1, 0}, {1, 0, 0}, {0, 0, 1})}, origin});
    return scene;
}

} // namespace radiant
