#pragma once
// Reading glTF accessors with every index and byte range checked first, so a hostile or truncated
// file ends in a RadiantError naming the element, never in a read past a buffer.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <tiny_gltf.h>

#include "radiometry/common/Error.h"

namespace radiant::detail {

/// The accessor `index` as VEC3 float positions. `where` names the primitive for messages.
std::vector<glm::dvec3> readPositions(const tinygltf::Model& model, int index, const SourceLocation& where);

/// The accessor `index` as unsigned integer indices (u8, u16 or u32).
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index, const SourceLocation& where);

/// Number of elements of accessor `index` (0 when it does not exist), for budgets before reading.
std::size_t accessorCount(const tinygltf::Model& model, int index);

} // namespace radiant::detail
