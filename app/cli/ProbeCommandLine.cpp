#include "app/cli/ProbeCommandLine.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>

#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app {

std::string roundTripNumber(double value) {
    if (value == 0) value = 0;  // "-0" reads back, but says nothing a reader needs
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return {buffer.data(), result.ptr};
}

std::string roundTripVector(const glm::dvec3& v) {
    return roundTripNumber(v.x) + "," + roundTripNumber(v.y) + "," + roundTripNumber(v.z);
}

std::string shellQuoted(std::string_view word) {
    const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               std::string_view("-_./,=+:@%").find(c) != std::string_view::npos;
    });
    if (safe) return std::string(word);
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string probeCommandLine(const ProbeCommandInputs& inputs) {
    std::string scene = inputs.scene;
    const std::vector<std::string> builtin = builtinSceneNames();
    if (std::find(builtin.begin(), builtin.end(), scene) == builtin.end()) {
        std::error_code ec;
        const std::filesystem::path absolute = std::filesystem::absolute(scene, ec);
        if (!ec) scene = absolute.lexically_normal().string();
    }
    std::string line = "radiant probe " + shellQuoted(scene);
    // "--option=value": a value starting with '-' (a negative coordinate) is never read as an option.
    line += " --point=" + roundTripVector(inputs.point);
    line += " --normal=" + roundTripVector(inputs.normal);
    if (inputs.target) line += " " + shellQuoted("--target=" + *inputs.target);
    line += " --method=" + std::string(methodName(inputs.method));
    line += " --max-patch-area=" + roundTripNumber(inputs.maxPatchArea);
    line += " --tolerance=" + roundTripNumber(inputs.tolerance);
    if (inputs.linkTolerance) line += " --link-tolerance=" + roundTripNumber(*inputs.linkTolerance);
    return line;
}

} // namespace radiant::app
