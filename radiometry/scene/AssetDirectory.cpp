#include "radiometry/scene/AssetDirectory.h"

#include <array>
#include <filesystem>

namespace radiant {
namespace {

namespace fs = std::filesystem;

/// Installed first: a build folder's link can only exist beside a build-tree executable.
std::array<fs::path, 2> candidates() {
    std::error_code ec;
    const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
    const fs::path folder = ec ? fs::path() : executable.parent_path();
    if (folder.empty()) return {};
    return {folder / ".." / "share" / "radiant" / "assets", folder / "assets"};
}

} // namespace

std::string assetDirectory() {
    for (const fs::path& candidate : candidates()) {
        std::error_code ec;
        if (!candidate.empty() && fs::is_directory(candidate, ec)) {
            const fs::path canonical = fs::weakly_canonical(candidate, ec);
            return (ec ? candidate : canonical).string();
        }
    }
    return {};
}

std::string assetDirectoryCandidates() {
    std::string list;
    for (const fs::path& candidate : candidates()) {
        if (candidate.empty()) continue;
        if (!list.empty()) list += " and ";
        list += candidate.lexically_normal().string();
    }
    return list.empty() ? "nowhere: the program's own path (/proc/self/exe) could not be read" : list;
}

} // namespace radiant
