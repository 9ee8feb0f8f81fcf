#pragma once
// A lecture demo is a sidebar panel (its sliders and numbers) that also draws in the 3D view: from
// its settings it builds a GL-free picture (render/demo/DemoDrawing.h) every frame, which the lab
// shows in place of the radiosity scene while the demo is open (DemoView.h), framed by the demo's
// own camera. The numbers in the picture come from the same functions as the panel's, which the
// unit tests check against the closed forms.
#include <optional>

#include <glm/vec3.hpp>

#include "app/panels/Panel.h"
#include "app/window/PickRay.h"
#include "render/camera/Camera.h"
#include "render/demo/DemoDrawing.h"

namespace radiant::app {

/// Where the 3D view looks when a demo opens, and the point it orbits.
struct DemoFraming {
    render::Camera camera;
    glm::dvec3 pivot{0.0};
    /// A figure wider than it is tall sets the narrowest view (width / height) it is framed for: a
    /// narrower view widens the camera's field to show that width (showingFramedWidth, through
    /// DemoView::shownCamera). 0: none.
    double framedAspect = 0;
};

/// A camera at `eye` looking at `target`, `fieldOfViewDegrees` vertical, depth range fitted to the
/// distance (the demos span metres, not the lab's 100 m default).
DemoFraming framingFrom(const glm::dvec3& eye, const glm::dvec3& target, double fieldOfViewDegrees);

/// `camera` with its field of view widened, in a view (width / height `aspect`) narrower than
/// `framedAspect`, so that it shows the framed width: a wide figure (the diffuse emitter's probes,
/// whose labels read to their right) in a tall view (no lesson caption, 1100 x 950 at UI scale 1.5)
/// had its sides cut by the vertical field alone and its labels pushed onto it. The lab draws, picks
/// and reports the demo's camera through this.
render::Camera showingFramedWidth(render::Camera camera, double aspect, double framedAspect);

class LectureDemo : public Panel {
public:
    [[nodiscard]] bool openByDefault() const override { return false; }
    /// The lesson files' name for the demo ("point-source", ...: lesson::demoIds()).
    [[nodiscard]] virtual const char* id() const = 0;
    /// The picture for the current settings; `cursor` is the pointer's ray through the 3D view
    /// when it is over it (a demo may read out a value where it points).
    [[nodiscard]] virtual render::DemoDrawing picture(const std::optional<PickRay>& cursor) const = 0;
    [[nodiscard]] virtual DemoFraming framing() const = 0;
};

} // namespace radiant::app
