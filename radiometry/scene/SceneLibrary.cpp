#include "radiometry/scene/SceneLibrary.h"

#include <algorithm>
#include <filesystem>

#include "radiometry/common/Error.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

namespace {

/// Every command and the lab solve what they load, and a scene without a source (no emitting surface,
/// no punctual light) solves to zero
/// everywhere ("residual 0", a black picture): refused before any form factor is computed.
LoadedScene requireEmitter(LoadedScene loaded) {
    if (!loaded.scene.lit()) {
        const std::size_t lights = loaded.ignoredLights;
        throw RadiantError({loaded.scene.name, ""},
                           "no surface emits and no light is supported: give a material an emissive colour "
                           "(emissiveFactor, with KHR_materials_emissive_strength for W/m^2, or extras.radiant.exitance_W_m2) "
                           "or add a KHR_lights_punctual point, spot or directional light" +
                               (lights == 0 ? std::string()
                                            : "; " + std::to_string(lights) + " KHR_lights_punctual light" + (lights == 1 ? "" : "s") +
                                                  " ignored (see the warnings)"));
    }
    return loaded;
}

} // namespace

LoadedScene loadScene(const std::string& nameOrPath, const SceneLoadOptions& options) {
    const std::vector<std::string> names = builtinSceneNames();
    if (std::find(names.begin(), names.end(), nameOrPath) == names.end()) return requireEmitter(loadGltf(nameOrPath, options));

    const std::string directory = assetDirectory();
    if (directory.empty())
        throw RadiantError({nameOrPath, ""}, "the built-in scenes' folder was not found (looked in " +
                                                 assetDirectoryCandidates() + ")");
    LoadedScene loaded = loadGltf((std::filesystem::path(directory) / (nameOrPath + ".gltf")).string(), options);
    loaded.scene.name = nameOrPath;
    return requireEmitter(std::move(loaded));
}

} // namespace radiant
