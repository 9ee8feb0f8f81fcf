#pragma once
// Scene: pick a built-in scene, open a glTF file (path or drag and drop), see the surface and
// patch counts, and set the meshing (largest patch area, and whether patches of smooth surfaces are
// grouped into unknowns of about that area). Files load on a worker (SceneJob); the
// solver thread meshes and solves. A failure is shown in red and the previous scene stays.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/panels/Panel.h"
#include "app/panels/SceneJob.h"
#include "app/solver/LiveSolve.h"

namespace radiant::app {

class ScenePanel final : public Panel {
public:
    /// `maxPatchArea` (m^2) meshes every scene opened from here; none: each scene opens at the area
    /// for its size (OpeningPatchArea.h), said under the slider. The knob re-meshes the scene shown.
    ScenePanel(LiveSolve& live, std::optional<double> maxPatchArea);

    [[nodiscard]] const char* title() const override { return "Scene"; }
    void update() override;
    void draw() override;

    /// Starts loading a built-in name or a .gltf/.glb path (the drop target calls this too).
    void open(const std::string& nameOrPath);
    [[nodiscard]] bool loading() const { return job_.running(); }
    [[nodiscard]] bool busy() const override { return loading(); }
    /// The area `scene` is to be meshed at when opened from here (the knob follows it).
    double patchAreaFor(const Scene& scene);

private:
    void drawMeshing();

    LiveSolve& live_;
    std::optional<double> fixedArea_;  ///< m^2 for every scene, else each scene's opening area
    double maxPatchArea_;  ///< m^2, asked of the solver thread
    float sliderAreaCm2_;  ///< the knob, in cm^2
    std::string openingReason_;  ///< why the scene opened at maxPatchArea_, until the knob moves
    /// The "Group patches" box, sent as command::SetGrouping: ticked, the default grouping (where
    /// it pays, DefaultGrouping.h); unticked, none.
    bool groupPatches_ = true;
    std::vector<std::string> builtins_;
    std::array<char, 1024> path_{};
    std::string error_;
    SceneJob job_;
};

} // namespace radiant::app
