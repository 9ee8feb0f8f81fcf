#pragma once
// The commands the UI sends to the solver thread. Each is a plain value; the worker applies them in
// order.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <variant>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/scene/View.h"
#include "radiometry/solver/DefaultGrouping.h"
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
    /// Part of the gesture the previous edit began (a slider still dragged, a field still typed in):
    /// the convergence plot keeps one segment for it (ConvergenceRecord.h).
    bool continuesEdit = false;
};
/// Every material back to the scene's as loaded (LoadScene's); the solve restarts from B = E.
struct ResetMaterials {};
struct SetTolerance {
    double tolerance;
};
/// Hierarchical and importance: SolverOptions::linkEpsilon; rebuilds the links.
struct SetLinkTolerance {
    double linkTolerance;
};
struct Remesh {
    MeshingOptions meshing;
};
/// How this mesh and every later one groups adjacent patches of a smooth surface into unknowns of
/// about the meshing's largest patch area (DefaultGrouping.h: Auto, the default, where that at least
/// halves a surface's patches; Off, the Scene panel's box unticked); rebuilds the solver.
/// Hierarchical and importance radiosity take no groups: picked, they solve the patches, and the
/// snapshot's grouping reason says so.
struct SetGrouping {
    GroupingMode mode = GroupingMode::Auto;
};
/// A point on the scene (the probe's pick) whose hierarchical links the snapshots single out: the
/// links of the element under it and of every ancestor, all of which it gathers through push-pull.
struct FocusedPoint {
    std::uint32_t surface = 0;
    std::uint32_t face = 0;  ///< within the surface
    glm::dvec3 point{0.0};   ///< m, on the face
    std::uint64_t meshGeneration = 0;  ///< the mesh it was picked on; another mesh ignores it
    bool operator==(const FocusedPoint&) const = default;
};
struct FocusPoint {
    std::optional<FocusedPoint> at;  ///< nullopt: none
};
/// The lab's camera, sent when it stops moving: importance-driven radiosity refines for this view
/// (from the current links and solution); other methods keep it for when importance is chosen. A
/// new scene forgets it (its home view applies until the next one).
struct SetView {
    View view;
};
/// Replaces the scene (already loaded and checked by the caller) and meshes it.
struct LoadScene {
    std::shared_ptr<const Scene> scene;
    MeshingOptions meshing;
};

} // namespace radiant::app::command

namespace radiant::app {
using SolverCommand = std::variant<command::Run, command::Pause, command::Step, command::Reset, command::SetMethod,
                                   command::SetMaterial, command::SetTolerance, command::Remesh, command::LoadScene,
                                   command::FocusPoint, command::SetLinkTolerance, command::SetView,
                                   command::ResetMaterials, command::SetGrouping>;
}
