#pragma once
// glTF PBR materials to diffuse radiosity materials in SI units (see GltfLoader.h for the mapping).
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "radiometry/scene/Scene.h"

namespace radiant::detail {

/// Material `index` of the model. Reflectance >= 1 is clamped to 0.999 with a warning; negative or
/// non-finite values throw RadiantError naming the file and material.
Material convertMaterial(const tinygltf::Model& model, std::size_t index, const std::string& file,
                         std::vector<std::string>& warnings);

} // namespace radiant::detail
