#pragma once
// Where the built-in scenes' .gltf files are, found from the running executable so that the
// program is relocatable: no path of the build machine is compiled in (a test reads the binary).
#include <string>

namespace radiant {

/// The folder holding the built-in scenes: <executable's folder>/../share/radiant/assets when
/// installed (bin/radiant beside share/radiant), else <executable's folder>/assets, the link a build
/// folder holds to the source tree's assets/ (CMakeLists.txt makes it). Empty when neither exists.
std::string assetDirectory();

/// The folders assetDirectory() looks in, for an error message that says where it looked.
std::string assetDirectoryCandidates();

} // namespace radiant
