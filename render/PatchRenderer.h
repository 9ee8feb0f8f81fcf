#pragma once
// Radiosity on screen: draws the patch mesh coloured by the newest per-patch radiosity (tone-mapped
// or false colour), smooth (Gouraud across each surface's conforming mesh) or flat, with overlays
// (wireframe, last shooter, changed patches, hierarchical links, importance). Streaming is cheap:
// geometry is uploaded when the mesh generation changes; display colours are worked out on the CPU
// when the solution generation, the exposure key or a colour setting changes, nothing otherwise,
// and uploaded as light-map texels for faces meshed as grids (FaceGrids.h: one quad per face) and
// as vertex colours for the other patches' triangles.
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

namespace radiant::render {

class PatchRenderer final : public SceneRenderer {
public:
    /// Compiles the shaders; draws nothing until setMesh. Needs a current GL context.
    PatchRenderer();
    ~PatchRenderer() override;
    PatchRenderer(PatchRenderer&&) noexcept;
    PatchRenderer& operator=(PatchRenderer&&) noexcept;
    PatchRenderer(const PatchRenderer&) = delete;
    PatchRenderer& operator=(const PatchRenderer&) = delete;

    /// Uploads the mesh's triangles (and the materials' colours) when meshGeneration differs from the
    /// last call's; otherwise returns at once. Clears radiosity, importance and links.
    void setMesh(const Scene& scene, const PatchMesh& mesh, std::uint64_t meshGeneration);
    /// Per-patch colours shown while there is no radiosity: reflectance, emitters at their exitance's
    /// chromaticity. Cheap; call when a material changes. The energy-balance exposure key is derived
    /// again only with `rekey` (setMesh does): a material edit keeps it, so the picture shows the
    /// change in light.
    void setMaterials(const Scene& scene, bool rekey = false);
    /// Per-patch radiosity in W/m^2, indexed like the mesh's patches (size must match, else throws
    /// RadiantError); uploaded only when `generation` differs from the last call's. An empty span
    /// means "no solution yet". `shooter` is the patch shot in the last step, or -1.
    void setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter = -1);
    /// Per-patch importance (any non-negative scale; shown relative to its maximum) for the
    /// importance tint. Null clears it; the pointer of the last call costs nothing.
    void setImportance(std::shared_ptr<const std::vector<double>> importance);
    /// Line segments (pairs of ends, metres) drawn when settings().showLinks: the hierarchical
    /// links. Null clears them; uploaded only when the pointer differs from the last call's.
    void setLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds);
    /// The links a picked point gathers through, drawn bright over the others when links are shown
    /// (the others fade further). Null clears them; uploaded only when the pointer changes.
    void setFocusLinks(std::shared_ptr<const std::vector<glm::vec3>> segmentEnds);

    void setSettings(const DisplaySettings& settings);
    [[nodiscard]] const DisplaySettings& settings() const;

    void draw(const Camera& camera, double aspect) const override;

    /// The range false colour maps with the current settings and data (for the legend).
    [[nodiscard]] ColourLegend legend() const;
    /// Radiosity (W/m^2) the tone map's exposure 0 shows as a middle tone, as settings().exposureKey
    /// asks (the automatic key where that mode has nothing to key on: no emitters, never re-keyed).
    [[nodiscard]] double exposureKeyW_m2() const;
    /// The area-weighted mean luminance of the lit non-emitting patches now (1 before any solution).
    [[nodiscard]] double automaticExposureKeyW_m2() const;
    /// Multiplier applied to radiosity before the tone curve: 2^stops * 0.35 / exposureKeyW_m2().
    [[nodiscard]] double exposureScale() const;

    [[nodiscard]] std::size_t patchCount() const;
    [[nodiscard]] bool hasRadiosity() const;
    /// How many times radiosity was actually uploaded (tests check that unchanged generations skip it).
    [[nodiscard]] std::uint64_t radiosityUploads() const;

private:
    /// Redoes the per-patch and per-vertex display colours when the data or the settings changed.
    void refreshColours() const;

    struct State;
    std::unique_ptr<State> state_;
};

} // namespace radiant::render
