#pragma once
// The hemicube on the GPU (M. F. Cohen and D. P. Greenberg, "The Hemi-Cube: A Radiosity Solution for
// Complex Environments", SIGGRAPH 1985): the mesh's patches rasterised from a point into the five
// faces of a half-cube about its normal, the depth test resolving visibility, each pixel keeping the
// patch it sees (an item buffer). The faces share one integer image laid out by HemicubeLayout;
// reading it back feeds gatherHemicube (form factors, irradiance) and the disk views. GL-free header.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/hemicube/HemicubeLayout.h"
#include "radiometry/mesh/PatchMesh.h"
#include "render/hemicube/HemicubeFrame.h"

namespace radiant::render {

struct HemicubeCapture {
    HemicubeLayout layout{2};
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 0, 1};
    /// The layout's local frame in the world: directions for pixelIndexOf go through frame.toLocal.
    HemicubeFrame frame{normal};
    /// HemicubeGather.h's encoding, row-major from the bottom row, layout.pixelCount() items.
    std::vector<std::uint32_t> items;
};

class HemicubeRenderer {
public:
    /// Uploads the patches. Needs a current GL context (3.3 core or later).
    explicit HemicubeRenderer(const PatchMesh& mesh);
    ~HemicubeRenderer();
    HemicubeRenderer(HemicubeRenderer&&) noexcept;
    HemicubeRenderer& operator=(HemicubeRenderer&&) noexcept;
    HemicubeRenderer(const HemicubeRenderer&) = delete;
    HemicubeRenderer& operator=(const HemicubeRenderer&) = delete;

    /// Renders the hemicube at x about the normal n (made unit), in HemicubeFrame(n), and reads its items back.
    /// Leaves the window framebuffer bound and the viewport as it found it. Throws RadiantError for
    /// a resolution HemicubeLayout refuses or a zero normal.
    HemicubeCapture capture(const glm::dvec3& x, const glm::dvec3& n, int resolution);
    /// Renders without reading back (the GPU part alone), for benchmarks; glFinish()es.
    void renderOnly(const glm::dvec3& x, const glm::dvec3& n, int resolution);

    [[nodiscard]] std::size_t patchCount() const { return patchCount_; }

private:
    struct GlState;
    void render(const glm::dvec3& x, const HemicubeFrame& frame, const HemicubeLayout& layout);
    std::unique_ptr<GlState> gl_;
    std::size_t patchCount_ = 0;
    double sceneSize_ = 1;  ///< m, the bounding box's diagonal: sets the near plane and the lift off the surface
};

} // namespace radiant::render
