#pragma once
// What the solver thread publishes and the main thread draws: an immutable picture of the solve.
// Shared through std::shared_ptr<const Snapshot>; nothing in it changes after publication, so the
// reader needs no lock and may keep it as long as it likes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/solver/ConvergenceRecord.h"
#include "app/solver/SolveHistory.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"

namespace radiant {
class RayCaster;
}

namespace radiant::app {

enum class SolverActivity {
    Idle,          ///< nothing to do: paused, converged, or no scene
    Meshing,       ///< cutting the scene into patches (progress available)
    FormFactors,   ///< building the solver: form factors, links (progress available)
    Solving,       ///< stepping
};

std::string_view activityName(SolverActivity activity);

struct Snapshot {
    std::uint64_t generation = 0;      ///< increases with every publication
    std::uint64_t meshGeneration = 0;  ///< increases when the scene or its mesh changes
    std::shared_ptr<const Scene> scene;     ///< materials as currently set
    std::shared_ptr<const PatchMesh> mesh;  ///< patches the radiosity below is indexed by
    /// The one ray caster of `scene`'s geometry (RayCaster.h: const queries, safe from any thread),
    /// the same object from LoadScene until the next one: materials edits and re-meshing keep it.
    /// Pickers, the probe and the path tracer share it; null with no scene.
    std::shared_ptr<const RayCaster> rays;
    std::vector<Rgb> radiosity;             ///< W/m^2 per patch and band; empty before a solver exists
    SolverMethod method = kSolveDefaults.method;
    /// Why `method` was chosen when the user has not picked one for this scene ("12,000 patches:
    /// progressive refinement's time grows ..."; DefaultMethod.h); empty once the user picks.
    std::string methodReason;
    IterationStats stats;                   ///< of the last step
    SolveHistory history;                   ///< every step of the segment being solved (ConvergenceRecord.h)
    ConvergenceRecord convergence;          ///< every method's earlier segments, for the overlaid plot
    bool running = false;                   ///< stepping by itself until converged or paused
    /// The last step came from a Step command (N in the lab), not from running: the 3D view outlines
    /// progressive's last shooter while the solve runs or is stepped, not once it has converged
    /// (a converged Cornell box showed a stray outline on the green wall: its last, tiny shot).
    bool lastStepByHand = false;
    double tolerance = kSolveDefaults.tolerance;  ///< running stops when the residual falls below this
    double linkTolerance = SolverOptions{}.linkEpsilon;  ///< hierarchical/importance refinement (SolverOptions)
    std::string error;                      ///< the last command's failure, empty when it succeeded
    /// Solvers built (each one a form-factor computation or initial linking) since the thread
    /// started: a materials edit must leave it unchanged.
    std::uint64_t solverBuilds = 0;
    MeshingOptions meshing;                 ///< what `mesh` was made with
    /// The patch groups solved as the unknowns (command::SetGrouping, DefaultGrouping.h), made from
    /// `mesh`; null when every patch is its own.
    std::shared_ptr<const PatchGroups> groups;
    /// Why grouped or not ("on: 810 patches in 312 groups (...)"), for the Scene panel.
    std::string groupingReason;
    /// The picked method takes no groups, so the patches are solved (groupingReason says so; the
    /// Solver panel shows it as a note).
    bool methodTakesNoGroups = false;
    /// Hierarchical and importance methods: every link as a segment between the centroids of the
    /// two elements it joins (pairs of ends, m). Shared by successive snapshots while the links
    /// stay the same (refinement is what changes them); null for the other methods.
    std::shared_ptr<const std::vector<glm::vec3>> linkSegments;
    /// Hierarchical and importance methods, with a focused point (command::FocusPoint) on this mesh:
    /// the links it gathers through, those of the element under it and of each ancestor, as segments
    /// from the point to each link's source centroid, and over how many levels of the element tree
    /// they stand. Null / 0 otherwise.
    std::shared_ptr<const std::vector<glm::vec3>> focusLinkSegments;
    std::size_t focusLevels = 0;
    /// Importance method: per-patch importance Y (1/m^2), indexed like the mesh's patches; null
    /// for the other methods.
    std::shared_ptr<const std::vector<double>> importance;
};

} // namespace radiant::app
