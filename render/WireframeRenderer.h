#pragma once
// The patch mesh drawn as lines over the scene, so students see what the solver's unknowns are.
// GL-free header; GL objects live in the implementation.
#include <memory>

#include "radiometry/mesh/PatchMesh.h"
#include "render/camera/Camera.h"

namespace radiant::render {

class WireframeRenderer {
public:
    /// Uploads every patch's edges. Needs a current GL context.
    explicit WireframeRenderer(const PatchMesh& mesh);
    ~WireframeRenderer();
    WireframeRenderer(WireframeRenderer&&) noexcept;
    WireframeRenderer& operator=(WireframeRenderer&&) noexcept;

    /// Draws over what is in the bound framebuffer, depth-tested against it (hidden edges stay hidden).
    void draw(const Camera& camera, double aspect) const;

private:
    struct GlState;
    std::unique_ptr<GlState> gl_;
};

} // namespace radiant::render
