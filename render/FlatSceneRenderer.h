#pragma once
// Draws a Scene's faces flat-shaded by material reflectance, with a little Lambert shading toward
// the eye so creases read. GL-free header; GL objects live in the implementation.
#include <memory>

#include "radiometry/scene/Scene.h"
#include "render/SceneRenderer.h"

namespace radiant::render {

class FlatSceneRenderer final : public SceneRenderer {
public:
    /// Uploads the scene's triangles. Needs a current GL context.
    explicit FlatSceneRenderer(const Scene& scene);
    ~FlatSceneRenderer() override;
    FlatSceneRenderer(FlatSceneRenderer&&) noexcept;
    FlatSceneRenderer& operator=(FlatSceneRenderer&&) noexcept;

    void draw(const Camera& camera, double aspect) const override;
    [[nodiscard]] std::size_t triangleCount() const;

private:
    struct GlState;
    std::unique_ptr<GlState> gl_;
};

} // namespace radiant::render
