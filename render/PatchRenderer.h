#pragma once
// Radiosity on screen: the GL drawer of the display model (render/display/DisplayModel.h, which
// decides every colour, tint, key and legend without GL). It holds the patch mesh on the GPU
// (triangles, and one light-mapped quad per grid face: render/display/FaceGrids.h), the display
// colours as vertex attributes (triangles indexed over each patch's corners; unindexed ones with
// barycentric edges for the wireframe and the shooter's outline) and atlas texels, the hierarchical
// links as lines, and draws them with back faces culled (a face is seen from its front only, so a
// closed room's near walls vanish).
// Geometry is uploaded when the mesh generation changes; colours when prepare() finds the model
// recoloured (new solution, exposure key, a colour setting); nothing otherwise.
// GL-free header; GL objects live in the implementation. Create, use and destroy on the GL thread.
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"
#include "render/ColourScale.h"
#include "render/DisplaySettings.h"
#include "render/SceneRenderer.h"
#include "render/display/DisplayModel.h"

namespace radiant::render {

class PatchRenderer final : public SceneRenderer {
public:
    /// Compiles the common shader variant; draws nothing until setMesh. Needs a current GL context.
    PatchRenderer();
    ~PatchRenderer() override;
    PatchRenderer(PatchRenderer&&) noexcept;
    PatchRenderer& operator=(PatchRenderer&&) noexcept;
    PatchRenderer(const PatchRenderer&) = delete;
    PatchRenderer& operator=(const PatchRenderer&) = delete;

    // The setters change the model (and upload geometry or lines); prepare() brings the GPU's colours
    // up to date before draw.

    /// Uploads the mesh's triangles and grid quads when meshGeneration differs from the last call's;
    /// otherwise returns at once. Clears radiosity, importance and links (DisplayModel::setMesh).
    void setMesh(const Scene& scene, const PatchMesh& mesh, std::uint64_t meshGeneration);
    /// DisplayModel::setMaterials: a material edit keeps the exposure key unless `rekey`.
    void setMaterials(const Scene& scene, bool rekey = false);
    /// DisplayModel::setRadiosity (W/m^2 per patch; wrong size throws RadiantError). `shooter` is
    /// the patch shot in the last step, or -1.
    void setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter = -1);
    /// DisplayModel::setImportance.
    void setImportance(std::shared_ptr<const std::vector<double>> importance);
    /// Line segments (pairs of ends, metres) drawn when settings().showLinks: the hierarchical
    /// links. Null clears them; uploaded only when the pointer differs from the last call's.
    void setLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds);
    /// The links a picked point gathers through, drawn bright over the others when links are shown
    /// (the others fade further). Null clears them; uploaded only when the pointer changes.
    void setFocusLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds);
    void setSettings(const DisplaySettings& settings);
    [[nodiscard]] const DisplaySettings& settings() const { return model_.settings(); }

    /// Recolours (DisplayModel::refreshColours) and uploads what changed: colour attributes, atlas
    /// texels, the shooter's outline cell; compiles the shader variants the settings need. Cheap when
    /// nothing changed. Call after the setters and before draw.
    void prepare();
    /// Draws what prepare() uploaded; changes no state of the renderer (an InvariantError when a
    /// setter ran since prepare()).
    void draw(const Camera& camera, double aspect) const override;

    [[nodiscard]] const DisplayModel& model() const { return model_; }
    [[nodiscard]] ColourLegend legend() const { return model_.legend(); }
    [[nodiscard]] double exposureKeyW_m2() const { return model_.exposureKeyW_m2(); }
    [[nodiscard]] double automaticExposureKeyW_m2() const { return model_.automaticExposureKeyW_m2(); }
    [[nodiscard]] double exposureScale() const { return model_.exposureScale(); }
    [[nodiscard]] std::size_t patchCount() const { return model_.patchCount(); }
    [[nodiscard]] bool hasRadiosity() const { return model_.hasRadiosity(); }
    /// How many solutions were taken (tests check that unchanged generations skip it).
    [[nodiscard]] std::uint64_t radiosityUploads() const { return model_.radiosityUpdates(); }

private:
    DisplayModel model_;
    bool prepared_ = false;
    struct Gpu;
    std::unique_ptr<Gpu> gpu_;
};

} // namespace radiant::render
