#include "radiometry/scene/SceneLibrary.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

namespace {

/// Every command and the lab solve what they load, and a scene without a source (no emitting surface,
/// no punctual light) solves to zero
/// everywhere ("residual 0", a black picture): refused before any form factor is computed.
/// A surface too crowded to cut along what stands on it (ContactCuts.h) is said once, at loading,
/// with the loader's warnings; the mesher and the element tree then leave it uncut alike.
void warnOfUncutContacts(LoadedScene& loaded) {
    std::vector<std::string> warnings;
    (void)detail::cutAlongContacts(loaded.scene, &warnings);
    for (const std::string& warning : warnings) {
        loaded.warnings.push_back(warning);
        loaded.scene.warnings.push_back(warning);
    }
}

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
    if (std::find(names.begin(), names.end(), nameOrPath) == names.end()) {
        LoadedScene loaded = requireEmitter(loadGltf(nameOrPath, options));
        warnOfUncutContacts(loaded);
        return loaded;
    }

    const std::string directory = assetDirectory();
    if (directory.empty())
        throw RadiantError({nameOrPath, ""}, "the built-in scenes' folder was not found (looked in " +
                                                 assetDirectoryCandidates() + ")");
    LoadedScene loaded = loadGltf((std::filesystem::path(directory) / (nameOrPath + ".gltf")).string(), options);
    loaded.scene.name = nameOrPath;
    loaded = requireEmitter(std::move(loaded));
    warnOfUncutContacts(loaded);
    return loaded;
}

} // namespace radiant
