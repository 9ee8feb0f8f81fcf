#pragma once
// What the glTF loader may open besides the glTF itself: the external buffers and images its URIs
// name, resolved against the glTF's own folder only (never the current directory), each a regular
// file within its stated byteLength and the loader's byte budget. A directory once ended in
// std::bad_alloc, a FIFO hung the loader and /dev/zero never ended: all are refused before opening.
// A path outside the scene's folder ("../textures/floor.png") is allowed (docs/RELIABILITY.md).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace radiant::detail {

/// Reads the glTF file itself (a regular file within the budget) or throws RadiantError naming it.
std::vector<unsigned char> readSceneFile(const std::string& path, std::uint64_t byteBudget);

/// Checks every external buffer and image URI of the glTF (text or .glb bytes) before tinygltf
/// reads any of them. Throws RadiantError (BudgetError over the budget) naming file, element and
/// URI for anything that is not a regular file of the right size; a missing image is only a
/// warning (the material then says what reflectance it used). Unparseable JSON is left to tinygltf.
void checkExternalFiles(std::span<const unsigned char> bytes, const std::filesystem::path& folder,
                        const std::string& file, std::uint64_t byteBudget, std::vector<std::string>& warnings);

/// File-system callbacks that open only absolute paths (tinygltf's fallback to the current
/// directory is relative, so it never matches) and only regular files within the budget: a
/// backstop behind checkExternalFiles. `byteBudget` must outlive the loader using the callbacks.
tinygltf::FsCallbacks sceneFolderFileSystem(const std::uint64_t& byteBudget);

} // namespace radiant::detail
