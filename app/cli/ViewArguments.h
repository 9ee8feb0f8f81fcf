#pragma once
// `--eye X,Y,Z --target X,Y,Z --fov DEG`: the view importance-driven radiosity refines for (and
// `render` draws), shared by solve, probe and render. Unset parts come from the scene's home view.
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "radiometry/scene/View.h"

namespace CLI {
class App;
}

namespace radiant::app {

/// "X,Y,Z" -> vector; anything else is a RadiantError naming the option and the value.
glm::dvec3 parseVector(const std::string& text, const char* option);

struct ViewArguments {
    std::string eye, target;
    double fovDegrees = 0;  ///< 0: unset
    /// The target's option: "--target", or "--look-at" in probe, whose --target names the surface
    /// it measures.
    const char* targetOption = "--target";
};

/// Registers --eye, arguments.targetOption and --fov.
void addViewOptions(CLI::App& command, ViewArguments& arguments);

/// The view the arguments describe, the scene's home view filling what they leave out; nullopt when
/// none is given (the solver then takes the home view itself). `aspect` is the image's width /
/// height. Throws RadiantError for a malformed vector, a field of view outside (0, 180) degrees or
/// an eye on the target.
std::optional<View> viewFromArguments(const ViewArguments& arguments, const Scene& scene, double aspect = 1.0);

} // namespace radiant::app
