#pragma once
// The commands the UI sends to the solver thread. Each is a plain value; the worker applies them in
// order.
#include <cstddef>
#include <memory>
#include <variant>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app::command {

struct Run {};
struct Pause {};
struct Step {
    std::size_t count = 1;
};
struct Reset {};
struct SetMethod {
    SolverMethod method;
};
struct SetMaterial {
    std::size_t surface;
    Rgb reflectance;
    ExitanceRgb exitance;
};
struct SetTolerance {
    double tolerance;
};
struct Remesh {
    MeshingOptions meshing;
};
/// Replaces the scene (already loaded and checked by the caller) and meshes it.
struct LoadScene {
    std::shared_ptr<const Scene> scene;
    MeshingOptions meshing;
};

} // namespace radiant::app::command

namespace radiant::app {
using SolverCommand = std::variant<command::Run, command::Pause, command::Step, command::Reset, command::SetMethod,
                                   command::SetMaterial, command::SetTolerance, command::Remesh, command::LoadScene>;
}
