#include "app/cli/ViewArguments.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant::app {

glm::dvec3 parseVector(const std::string& text, const char* option) {
    glm::dvec3 v(0.0);
    std::size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t end = axis < 2 ? text.find(',', start) : text.size();
        bool ok = end != std::string::npos && end > start;
        if (ok) {
            const std::string field = text.substr(start, end - start);
            char* parsedEnd = nullptr;
            v[axis] = std::strtod(field.c_str(), &parsedEnd);
            ok = parsedEnd == field.c_str() + field.size() && std::isfinite(v[axis]);
        }
        if (!ok) throw RadiantError({"", option}, "expected three numbers X,Y,Z, got '" + text + "'");
        start = end + 1;
    }
    return v;
}

void addViewOptions(CLI::App& command, ViewArguments& arguments) {
    command.add_option("--eye", arguments.eye, "X,Y,Z: the camera importance refines for (default: the home view)");
    command.add_option(arguments.targetOption, arguments.target, "X,Y,Z: the point that camera looks at");
    command.add_option("--fov", arguments.fovDegrees, "that camera's vertical field of view, degrees");
}

std::optional<View> viewFromArguments(const ViewArguments& arguments, const Scene& scene, double aspect) {
    if (arguments.eye.empty() && arguments.target.empty() && arguments.fovDegrees == 0) return std::nullopt;
    View view = homeView(scene);
    view.aspect = aspect;
    if (!arguments.eye.empty()) view.eye = parseVector(arguments.eye, "--eye");
    if (!arguments.target.empty()) view.target = parseVector(arguments.target, arguments.targetOption);
    if (arguments.fovDegrees != 0) {
        if (!(arguments.fovDegrees > 0 && arguments.fovDegrees < 180))
            throw RadiantError({"", "--fov"}, "must lie in (0, 180) degrees, got " + std::to_string(arguments.fovDegrees));
        view.verticalFov = arguments.fovDegrees * std::numbers::pi / 180.0;
    }
    if (!(glm::length(view.target - view.eye) > 0))
        throw RadiantError({"", "--eye"}, "the eye lies on the target: the camera looks nowhere");
    return view;
}

} // namespace radiant::app
