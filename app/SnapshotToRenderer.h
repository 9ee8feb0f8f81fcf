#pragma once
// What a snapshot hands the 3D view's renderer each frame: the mesh, the materials when they changed,
// the radiosity, links and importance. Each upload happens only when its generation or pointer
// moved, so calling this every frame costs nothing while the solver is idle. One function for the
// lab's solver and the comparison's second one.
#include <memory>

#include "app/solver/Snapshot.h"
#include "render/PatchRenderer.h"

namespace radiant::app {

/// `materialsShown` is the scene whose materials the renderer holds; updated here.
void streamSnapshotToRenderer(const Snapshot& snapshot, render::PatchRenderer& renderer,
                              std::shared_ptr<const Scene>& materialsShown);

} // namespace radiant::app
