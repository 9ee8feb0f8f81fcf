#pragma once
// glTF cameras (core glTF 2.0, "cameras" placed by the nodes that reference them) into
// SceneCamera: the node's world transform gives the eye, its local -z the view direction and its
// local +y the up vector, as the glTF specification defines a camera's frame.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "radiometry/scene/Scene.h"

namespace radiant::detail {

/// The perspective camera `index` placed by a node named `nodeName` with `world`; nullopt (with a
/// warning naming it) for an orthographic or degenerate camera, which Radiant does not use.
std::optional<SceneCamera> readCamera(const tinygltf::Model& model, int index, const std::string& nodeName,
                                      const glm::dmat4& world, const std::string& file, std::vector<std::string>& warnings);

} // namespace radiant::detail
