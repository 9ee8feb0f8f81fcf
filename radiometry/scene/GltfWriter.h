#pragma once
// Writes a Scene as glTF 2.0, so the built-in scenes ship as files any viewer opens and the loader
// can be tested on them. One mesh and one node per surface (node name = surface name), faces as
// triangle fans, materials with baseColorFactor, emissiveFactor x KHR_materials_emissive_strength
// and extras.radiant {reflectance, exitance_W_m2} holding the exact SI values.
#include <string>

#include "radiometry/scene/Scene.h"

namespace radiant {

/// Writes `scene` to `path`: .glb writes binary glTF, anything else .gltf with the buffer embedded
/// as base64. Throws RadiantError when the file cannot be written.
void writeGltf(const Scene& scene, const std::string& path);

} // namespace radiant
