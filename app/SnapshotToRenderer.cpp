#include "app/SnapshotToRenderer.h"

namespace radiant::app {

void streamSnapshotToRenderer(const Snapshot& snapshot, render::PatchRenderer& renderer,
                              std::shared_ptr<const Scene>& materialsShown) {
    if (!snapshot.scene || !snapshot.mesh) return;
    renderer.setMesh(*snapshot.scene, *snapshot.mesh, snapshot.meshGeneration);
    if (snapshot.scene != materialsShown) {
        renderer.setMaterials(*snapshot.scene);
        materialsShown = snapshot.scene;
    }
    const bool shooting = snapshot.running || snapshot.lastStepByHand;
    renderer.setRadiosity(snapshot.radiosity, snapshot.generation, shooting ? snapshot.stats.shooter : -1);
    renderer.setLinks(snapshot.linkSegments);
    renderer.setFocusLinks(snapshot.focusLinkSegments);
    renderer.setImportance(snapshot.importance);
}

} // namespace radiant::app
