#pragma once
// The lab's side of the comparison mode (app/solver/Comparison.h; the second solver thread lives in
// LiveSolve): a renderer for solution B and one for the difference view, the split of the 3D view
// into halves drawn with one camera, and the labels and legend over them. Off, it draws the one
// solution in the whole view as before. Main thread only (GL); GL-free header.
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "app/solver/LiveSolve.h"
#include "app/solver/SolutionDifference.h"
#include "render/DisplaySettings.h"
#include "render/PatchRenderer.h"
#include "render/camera/Camera.h"

namespace radiant::app {

class LabComparison {
public:
    explicit LabComparison(LiveSolve& live) : live_(live) {}

    /// V: off -> side by side -> difference -> off.
    void cycle();
    /// Hands B's newest snapshot (and, in the difference view, the difference) to their renderers.
    void stream(const render::DisplaySettings& display, const render::PatchRenderer& first);
    /// The difference view is up with a difference to draw: A's own colours are not on screen (the
    /// lab then leaves A's renderer alone, and streams it again when A shows).
    [[nodiscard]] bool hidesFirst() const;
    /// The viewports the 3D view is drawn in this frame, in framebuffer pixels: `view` itself, or its
    /// two halves (A left, B right) side by side.
    [[nodiscard]] std::vector<render::Viewport> views(const render::Viewport& view) const;
    /// Draws A (`first`, prepared), B or the difference into views(view); leaves the first of them as
    /// the GL viewport (the overlays that follow draw over A).
    void draw(render::PatchRenderer& first, const render::DisplaySettings& display, const render::Camera& camera,
              const render::Viewport& view, int framebufferHeight);
    /// The halves' labels (method, iteration, residual) and the difference view's legend, over the
    /// view in UI units; true when it drew a legend (the lab's own then stays away).
    bool drawOverlays(const render::Viewport& viewInUiUnits) const;
    /// The difference last computed (mesh null when none).
    [[nodiscard]] const SolutionDifference& difference() const { return differencer_.current(); }
    /// GL objects go while the context lives.
    void release();

    /// The difference view's colour map: log10 over DisplaySettings::kLogDecades decades below 1.
    static constexpr float kDifferenceTop = 1.0f;
    /// The difference view outlines its patches up to this many (the lab's default meshes).
    static constexpr std::size_t kMostPatchesWithEdges = 8000;
    /// How often the difference view is redone while either side solves.
    static constexpr double kDifferenceHz = 10.0;

private:
    LiveSolve& live_;
    std::optional<render::PatchRenderer> second_, difference_;
    std::shared_ptr<const Scene> secondMaterials_;
    SolutionDifferencer differencer_;
    std::chrono::steady_clock::time_point differenceComputedAt_{};
    std::uint64_t differenceShown_ = 0;   ///< the difference generation uploaded
    std::shared_ptr<const PatchMesh> differenceMesh_;
    std::uint64_t differenceMeshKey_ = 0;  ///< bumped when the difference's mesh changes
    std::vector<Rgb> differenceValues_;
};

} // namespace radiant::app
