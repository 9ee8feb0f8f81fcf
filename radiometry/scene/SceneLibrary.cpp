#include "radiometry/scene/SceneLibrary.h"

#include <algorithm>
#include <filesystem>

#include "radiometry/common/Error.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {

std::string assetDirectory() {
    namespace fs = std::filesystem;
    std::error_code ec;
#ifdef RADIANT_ASSET_DIR
    if (fs::is_directory(RADIANT_ASSET_DIR, ec)) return RADIANT_ASSET_DIR;
#endif
    const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = executable.parent_path() / ".." / "share" / "radiant" / "assets";
        if (fs::is_directory(installed, ec)) return fs::weakly_canonical(installed, ec).string();
    }
    return {};
}

LoadedScene loadScene(const std::string& nameOrPath, const SceneLoadOptions& options) {
    const std::vector<std::string> names = builtinSceneNames();
    if (std::find(names.begin(), names.end(), nameOrPath) == names.end()) return loadGltf(nameOrPath, options);

    const std::string directory = assetDirectory();
    if (directory.empty())
        throw RadiantError({nameOrPath, ""}, "the built-in scenes' folder was not found (looked in " +
                                                 std::string(RADIANT_ASSET_DIR) + " and ../share/radiant/assets beside the program)");
    LoadedScene loaded = loadGltf((std::filesystem::path(directory) / (nameOrPath + ".gltf")).string(), options);
    loaded.scene.name = nameOrPath;
    return loaded;
}

} // namespace radiant
