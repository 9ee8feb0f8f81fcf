#pragma once
// Scene: pick a built-in scene, open a glTF file (path or drag and drop), see the surface and
// patch counts, and set the meshing (largest patch area). Loading and meshing run on a worker;
// a failure is shown in red and the previous scene stays.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "app/panels/Panel.h"
#include "app/panels/SceneJob.h"

namespace radiant::app {

class ScenePanel final : public Panel {
public:
    /// Called on the main thread with each newly loaded or re-meshed scene.
    using Install = std::function<void(const Scene&, const PatchMesh&)>;

    ScenePanel(Install install, Scene initial, double maxPatchArea);

    [[nodiscard]] const char* title() const override { return "Scene"; }
    void update() override;
    void draw() override;

    /// Starts loading a built-in name or a .gltf/.glb path (the drop target calls this too).
    void open(const std::string& nameOrPath);
    [[nodiscard]] bool showWireframe() const { return showWireframe_; }
    [[nodiscard]] bool busy() const { return job_.running(); }

private:
    void drawMeshing();

    Install install_;
    Scene scene_;
    std::size_t patchCount_ = 0;
    double maxPatchArea_;        ///< m^2, of the current mesh
    float sliderAreaCm2_;        ///< the knob, in cm^2
    bool showWireframe_ = true;
    std::vector<std::string> builtins_;
    std::array<char, 1024> path_{};
    std::string error_;
    std::vector<std::string> warnings_;
    SceneJob job_;
};

} // namespace radiant::app
