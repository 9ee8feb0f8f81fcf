#pragma once
// KHR_lights_punctual lights into PunctualLight (SI units, per band). glTF gives a point or spot
// light's intensity in candela and a directional light's in lux; one luminous efficacy (179 lm/W,
// Photometry.h) turns them into W/sr and W/m^2, spread over the bands in the light's colour at the
// same luminance Y, so a white lamp of I cd gives I / d^2 lx on a facing surface at distance d.
// The node's world transform places the light at its origin, shining down its local -z.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "radiometry/sources/PunctualLight.h"

namespace radiant::detail {

/// The light index a node's KHR_lights_punctual extension names, or -1 when it names none.
/// Throws RadiantError when the extension is there but its "light" is not an index.
int nodeLightIndex(const tinygltf::Node& node, const std::string& nodeName, const std::string& file);

/// Light `index` placed by node `nodeName` with `world`; nullopt (with a warning naming it) for a
/// light that gives no light (zero intensity or black colour), an unknown type or a transform that
/// collapses its direction. Throws RadiantError (one line: file, light, value) for an index out of
/// range, a negative or non-finite intensity or colour, or spot cone angles outside
/// 0 <= inner < outer <= pi/2.
std::optional<PunctualLight> readLight(const tinygltf::Model& model, int index, const std::string& nodeName,
                                       const glm::dmat4& world, const std::string& file, std::vector<std::string>& warnings);

} // namespace radiant::detail
