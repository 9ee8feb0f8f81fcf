#pragma once
// What the lab draws the 3D view with. The flat renderer (reflectance colours) is the first; the patch
// renderer (per-patch radiosity) replaces it behind this interface. Implementations own GL objects,
// so create, draw and destroy them on the GL thread only. GL-free header.
#include "render/camera/Camera.h"

namespace radiant::render {

class SceneRenderer {
public:
    virtual ~SceneRenderer() = default;
    /// Draws into the currently bound framebuffer, whose viewport the caller has set; `aspect` is that
    /// viewport's width / height.
    virtual void draw(const Camera& camera, double aspect) const = 0;
};

} // namespace radiant::render
