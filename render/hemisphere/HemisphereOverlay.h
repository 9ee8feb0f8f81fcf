#pragma once
// "The sky of the point" in the 3D view: a dome standing on the probe point, oriented on the surface
// normal, painted with what the point sees (a hemicube's equidistant fisheye image, Cohen & Greenberg
// 1985) and drawn see-through over the scene, with the theta/phi grid of d omega cells. A direction d
// from the point is painted where it leaves the dome, at centre + radius d: the light overhead sits at
// the dome's top, a wall near its rim on the wall's side. Drawn after the scene, depth-tested against
// it and writing no depth. GL-free header; create, draw and destroy on the GL thread.
#include <cstdint>
#include <memory>
#include <span>

#include <glm/vec3.hpp>

#include "render/SceneRenderer.h"
#include "render/hemicube/HemicubeFrame.h"

namespace radiant::render {

struct HemisphereOverlayPlacement {
    glm::dvec3 centre{0.0};         ///< m: the probe point
    HemicubeFrame frame{{0, 0, 1}};  ///< the image's local frame (z = the surface normal)
    double radius = 0.1;            ///< m
};

struct HemisphereOverlayStyle {
    float opacity = 0.8f;  ///< of the near side; the far side (seen through it) at half
    bool grid = true;      ///< theta every 15 degrees, phi every 30 degrees, as the Hemisphere panel's
};

class HemisphereOverlay final : public SceneRenderer {
public:
    /// Compiles the shaders and builds the dome. Needs a current GL context.
    HemisphereOverlay();
    ~HemisphereOverlay() override;
    HemisphereOverlay(HemisphereOverlay&&) noexcept;
    HemisphereOverlay& operator=(HemisphereOverlay&&) noexcept;
    HemisphereOverlay(const HemisphereOverlay&) = delete;
    HemisphereOverlay& operator=(const HemisphereOverlay&) = delete;

    /// The sky: an equidistant fisheye of HemisphereViewMap(layout, Equidistant, size, upAzimuth), RGBA8,
    /// size x size, top row first (hemisphereImage's output, best without its grid: the dome draws its own).
    void setImage(int size, std::span<const std::uint8_t> rgba, double upAzimuth);
    void setPlacement(const HemisphereOverlayPlacement& placement);
    void setStyle(const HemisphereOverlayStyle& style);
    [[nodiscard]] bool hasImage() const;

    /// Draws the dome over whatever the bound framebuffer holds (blended, depth-tested, no depth
    /// writes); nothing before setImage. Restores the blend, depth and cull state it changes.
    void draw(const Camera& camera, double aspect) const override;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace radiant::render
