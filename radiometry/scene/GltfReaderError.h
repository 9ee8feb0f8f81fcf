#pragma once
// tinygltf's error text made into one line of a sensible length. Its JSON parser quotes everything it
// read of the failing token ("last read: '...'"), which for a broken data URI is a kilobyte of base64:
// the line keeps where the parser stopped (line and column) and why, and only the last few
// characters read.
#include <cstddef>
#include <string>

namespace radiant::detail {

/// At most `maxLength` characters (an ellipsis marks a cut), no line breaks; empty text becomes
/// "not a glTF file".
std::string gltfReaderErrorLine(const std::string& readerError, std::size_t maxLength = 160);

} // namespace radiant::detail
