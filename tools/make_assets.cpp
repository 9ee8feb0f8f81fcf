// Writes every built-in scene (built in code, radiometry/scene/) to <dir>/<name>.gltf, so the
// shipped assets can be remade and reviewed as code. Usage: radiant_make_assets [OUTPUT_DIR]
// (default: the source tree's assets/).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/scene/GltfWriter.h"

int main(int argc, char** argv) {
    const std::filesystem::path directory = argc > 1 ? argv[1] : RADIANT_ASSET_DIR;
    try {
        std::filesystem::create_directories(directory);
        for (const std::string& name : radiant::builtinSceneNames()) {
            const std::filesystem::path file = directory / (name + ".gltf");
            radiant::writeGltf(radiant::makeBuiltinScene(name), file.string());
            std::printf("wrote %s\n", file.string().c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiant_make_assets: %s\n", e.what());
        return 2;
    }
    return 0;
}
