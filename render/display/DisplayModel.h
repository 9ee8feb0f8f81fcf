#pragma once
// What the 3D view shows, worked out without GL (so it is unit-tested without a display): per-patch
// and per-vertex display colours (tone-mapped, false colour or reflectance), tints (importance,
// changed patches, the last shooter), the exposure key, the false-colour legend's automatic range,
// and the change detection between solutions. The GL drawer (render/PatchRenderer) uploads what
// this makes; it never decides a colour. Single-threaded: owned by whoever draws.
#include <cstdint>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <vector>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "render/ColourScale.h"
#include "render/DisplaySettings.h"
#include "render/display/FaceGrids.h"
#include "render/display/SmoothingGroups.h"

namespace radiant::render {

/// Radiosity the tone map's exposure 0 shows as this input of the tone curve: a middle tone.
inline constexpr double kKeyTone = 0.35;

/// One patch's tint: rgb the colour mixed toward, w the amount in [0, 1), plus 2 when the patch is
/// outlined (the last shooter).
using Tint = glm::vec4;

/// Successive tints mix(mix(c, a.rgb, a.w), b.rgb, b.w) as one mix toward a combined colour.
Tint addTint(const Tint& a, const Tint& b);

/// Display colours as the shaders take them: rgb sRGB-encoded, a the position on the colour map
/// (false colour only; 0 otherwise). A false-colour solution leaves rgb 0: the shader maps a alone.
struct DisplayColours {
    std::vector<glm::vec4> patch;   ///< per patch: flat shading, and reflectance before a solution
    std::vector<glm::vec4> vertex;  ///< per smoothing vertex: smooth shading
    std::vector<Tint> tint;         ///< per patch
    bool smooth = true;             ///< vertex (else patch) holds the colours shown
    bool falseColour = false;       ///< alpha holds colour-map positions
    bool anyTint = false;           ///< some patch is tinted or outlined
};

class DisplayModel {
public:
    /// Copies what colouring needs from the mesh (areas, surfaces, smoothing groups, grid faces);
    /// clears radiosity and importance and derives the energy-balance key anew.
    void setMesh(const Scene& scene, const PatchMesh& mesh);
    /// Base colours (reflectance; emitters at their exitance's chromaticity). The energy-balance
    /// key is derived again only with `rekey` (setMesh does): a material edit keeps it, so doubling a
    /// lamp doubles what the picture shows.
    void setMaterials(const Scene& scene, bool rekey = false);
    /// Per-patch radiosity in W/m^2 (size must match the mesh, else RadiantError); empty = no
    /// solution. Returns false, doing nothing, when `generation` and emptiness match the last call.
    bool setRadiosity(std::span<const Rgb> radiosityW_m2, std::uint64_t generation, std::int64_t shooter);
    /// Per-patch importance, any non-negative scale (shown relative to its maximum); null clears it.
    /// The pointer of the last call costs nothing.
    void setImportance(std::shared_ptr<const std::vector<double>> importance);
    void setSettings(const DisplaySettings& settings);
    [[nodiscard]] const DisplaySettings& settings() const { return settings_; }

    /// Redoes the display colours if the data or a setting they depend on changed since the last
    /// call; returns whether it did (the drawer then uploads them).
    bool refreshColours();
    [[nodiscard]] const DisplayColours& colours() const { return colours_; }

    /// The range false colour maps with the current settings and data.
    [[nodiscard]] ColourLegend legend() const;
    /// Radiosity (W/m^2) exposure 0 shows as a middle tone, as settings().exposureKey asks (the
    /// automatic key where that mode has nothing to key on: no emitters, never re-keyed).
    [[nodiscard]] double exposureKeyW_m2() const;
    /// The area-weighted mean luminance of the lit non-emitting patches now (1 before any solution).
    [[nodiscard]] double automaticExposureKeyW_m2() const { return automaticKeyW_m2_; }
    /// Multiplier applied to radiosity before the tone curve: 2^stops * kKeyTone / exposureKeyW_m2().
    [[nodiscard]] double exposureScale() const;

    [[nodiscard]] std::size_t patchCount() const { return patchSurface_.size(); }
    [[nodiscard]] bool hasRadiosity() const { return hasRadiosity_; }
    [[nodiscard]] std::int64_t shooter() const { return hasRadiosity_ ? shooter_ : -1; }
    /// Per patch: the last shot changed its radiosity visibly (all zero after a gathering step).
    [[nodiscard]] const std::vector<char>& changed() const { return changed_; }
    /// Per smoothing vertex, W/m^2: the area-weighted mean of the patches around it. Made when first
    /// asked after a new solution (smooth shading asks; flat shading, the difference view's, never does).
    [[nodiscard]] const std::vector<Rgb>& smoothRadiosity() const;
    [[nodiscard]] const SmoothingGroups& smoothing() const { return smoothing_; }
    [[nodiscard]] const FaceGrids& grids() const { return grids_; }
    /// How many solutions setRadiosity took.
    [[nodiscard]] std::uint64_t radiosityUpdates() const { return updates_; }

private:
    /// Everything the colours depend on besides the data: when it changes, they are redone.
    struct ColourInputs {
        double exposureScale = 0;
        ColourMode mode = ColourMode::ToneMapped;
        bool logScale = false;
        float falseColourMaxW_m2 = 0;
        bool highlight = false;
        bool importance = false;
        Shading shading = Shading::Smooth;
        bool photometric = false;
        bool operator==(const ColourInputs&) const = default;
    };
    [[nodiscard]] ColourInputs colourInputs() const;
    [[nodiscard]] double dataMaxW_m2() const;
    /// What false colour maps for radiosity `b` on `patch` (or a vertex of it), in the legend's unit:
    /// total radiosity in W/m^2, or with photometric units the illuminance in lx; NaN where it
    /// cannot be known (illuminance on a surface black in some band).
    [[nodiscard]] double mappedValue(const Rgb& b, std::size_t patch) const;
    void makeTints(const ColourInputs& inputs);

    DisplaySettings settings_;
    std::vector<std::uint32_t> patchSurface_;
    std::vector<double> patchArea_;
    std::vector<char> patchEmits_;
    std::vector<glm::vec3> baseColour_;  // linear: reflectance, or an emitter's chromaticity
    std::vector<Rgb> patchReflectance_;
    std::vector<Rgb> patchExitance_;     // W/m^2
    std::vector<std::uint32_t> vertexPatch_;  // per smoothing vertex: a patch it belongs to (one surface)
    SmoothingGroups smoothing_;
    FaceGrids grids_;
    std::vector<double> importance_;  // relative to its maximum
    std::shared_ptr<const std::vector<double>> importanceShown_;

    bool hasRadiosity_ = false;
    std::uint64_t generation_ = 0;
    std::uint64_t updates_ = 0;
    std::int64_t shooter_ = -1;
    std::vector<Rgb> radiosity_;        // per patch, W/m^2
    mutable std::vector<Rgb> smoothRadiosity_;  // per smoothing vertex, W/m^2; a memo, like dataMaxMemoW_m2_
    mutable bool smoothRadiosityStale_ = false;
    std::vector<char> changed_;

    double automaticKeyW_m2_ = 1.0;      // mean luminance of the lit reflectors now
    double energyBalanceKeyW_m2_ = 0.0;  // from the materials; 0 when nothing emits
    double heldKeyW_m2_ = 0.0;           // 0 until re-keyed
    unsigned rekeysSeen_ = 0;
    // The 99th area percentile behind the automatic false-colour range, sorted only when asked (a
    // memo: legend() is const, and the tone-mapped view never asks).
    mutable double dataMaxMemoW_m2_ = 1.0;
    mutable bool dataMaxStale_ = false;

    bool coloursDirty_ = true;
    ColourInputs coloursMadeWith_;
    DisplayColours colours_;
    ToneCurveTable toneCurve_;
};

} // namespace radiant::render
