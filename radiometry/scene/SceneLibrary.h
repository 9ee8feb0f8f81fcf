#pragma once
// One entry point for "a scene" wherever the user names one (command line, Scene panel, drag and
// drop): a built-in name ("cornell-box", "unit-cube", ...) or a path to a .gltf/.glb file.
#include <string>
#include <vector>

#include "radiometry/scene/AssetDirectory.h"
#include "radiometry/scene/GltfLoader.h"

namespace radiant {

/// Names of the built-in scenes, "cornell-box" first (same list as BuiltinScenes.h).
std::vector<std::string> builtinSceneNames();

/// Loads a scene. A built-in name loads <assetDirectory()>/<name>.gltf (the same file any glTF
/// viewer opens) and keeps the name as Scene::name; anything else is a path to a glTF file.
/// Throws RadiantError (one line naming file and element) on bad input, BudgetError over budget,
/// and RadiantError for a scene in which no surface emits and no light shines (nothing to solve; loadGltf loads it).
LoadedScene loadScene(const std::string& nameOrPath, const SceneLoadOptions& options = {});

} // namespace radiant
