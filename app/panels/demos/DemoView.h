#pragma once
// Which lecture demo the 3D view shows, if any, and the user's camera on the radiosity scene while
// it does: opening a demo puts the scene's orbit camera aside and frames the demo; closing it gives
// the camera back as it was. The solve, probe and display are never touched, so the scene comes back
// whole. GL-free; owned by the lab, used by the demos panel and the lesson stage.
#include <optional>

#include "render/camera/Camera.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {

class LectureDemo;

class DemoView {
public:
    /// Keeps a reference: the camera the lab's 3D view and controller use.
    explicit DemoView(render::OrbitCamera& orbit) : orbit_(orbit) {}

    /// Shows `demo` in the 3D view at its framing; a second demo replaces the first and keeps the
    /// scene's camera put aside by the first.
    void open(const LectureDemo& demo);
    /// Back to the scene and its camera; nothing when no demo is open.
    void close();
    [[nodiscard]] const LectureDemo* active() const { return active_; }
    /// The camera the open demo is drawn, picked and reported through in a view of this aspect
    /// (width / height): `orbitCamera` widened to the width the demo is framed for
    /// (showingFramedWidth); `orbitCamera` itself with no demo open.
    [[nodiscard]] render::Camera shownCamera(const render::Camera& orbitCamera, double aspect) const;
    /// The scene's camera, wherever it is kept now (a scene loaded during a demo re-homes this one,
    /// and a saved session records it, not the demo's).
    [[nodiscard]] render::OrbitCamera& sceneCamera() { return sceneCamera_ ? *sceneCamera_ : orbit_; }

private:
    render::OrbitCamera& orbit_;
    std::optional<render::OrbitCamera> sceneCamera_;  ///< put aside while a demo is open
    const LectureDemo* active_ = nullptr;
    double framedAspect_ = 0;  ///< the open demo's DemoFraming::framedAspect
};

} // namespace radiant::app
