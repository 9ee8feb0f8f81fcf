#include <functional>
#include <utility>

#include "radiometry/common/Error.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {
namespace {

const std::vector<std::pair<std::string, std::function<Scene()>>>& registry() {
    static const std::vector<std::pair<std::string, std::function<Scene()>>> scenes{
        {"cornell-box", makeCornellBox},
        {"unit-cube", makeUnitCube},
        {"furnace", makeFurnace},
        {"parallel-plates", makeParallelPlates},
        {"perpendicular-plates", makePerpendicularPlates},
    };
    return scenes;
}

} // namespace

std::vector<std::string> builtinSceneNames() {
    std::vector<std::string> names;
    for (const auto& entry : registry()) names.push_back(entry.first);
    return names;
}

Scene makeBuiltinScene(const std::string& name) {
    for (const auto& [known, make] : registry())
        if (known == name) return make();
    std::string list;
    for (const auto& entry : registry()) list += (list.empty() ? "" : ", ") + entry.first;
    throw RadiantError({name, ""}, "not a built-in scene (built-in scenes: " + list + ")");
}

} // namespace radiant
