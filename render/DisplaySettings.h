#pragma once
// How radiosity is shown: the knobs of the Display panel, read by render/display/DisplayModel. Plain values,
// GL-free, owned by the lab and edited in place by the panel.
namespace radiant::render {

enum class Shading {
    Smooth,  ///< Gouraud: per-vertex radiosity = area-weighted mean of the surface's adjacent patches
    Flat,    ///< each patch shows its own radiosity: the solver's unknowns as they are
};

enum class ColourMode {
    ToneMapped,   ///< exposure, ACES-fitted tone curve, sRGB-encoded: what an eye would see
    FalseColour,  ///< luminance in W/m^2 through the viridis colour map, with a legend
    Reflectance,  ///< each surface in its material's reflectance (sRGB), whatever the solution: the
                  ///< scene as built, to compare with what light makes of it
};

/// Which radiosity exposure 0 shows as a middle tone.
enum class ExposureKey {
    /// Fixed by the emitters and materials alone: the mean radiosity the reflectors reach once all
    /// the emitted power is absorbed (energy balance of a closed, well-mixed enclosure). The image
    /// starts dark and brightens as the solve spreads light, ending about right.
    EnergyBalance,
    /// The automatic key of the solution shown when it was re-keyed (button, key K), then fixed.
    Held,
    /// The mean radiosity of the lit reflectors, every frame: always well exposed, but a solve in
    /// progress hardly seems to brighten.
    Automatic,
};

struct DisplaySettings {
    /// Exposure in stops relative to the key (see ExposureKey); +1 doubles the light.
    float exposureStops = 0.0f;
    ExposureKey exposureKey = ExposureKey::EnergyBalance;
    /// Bumped to re-key: the renderer then holds the automatic key of the solution it shows.
    unsigned rekeyCount = 0;
    Shading shading = Shading::Smooth;
    ColourMode colourMode = ColourMode::ToneMapped;
    /// False colour on a log10 scale spanning kLogDecades decades below the maximum.
    bool logScale = false;
    /// W/m^2 mapped to the top of the colour map; 0 = automatic (the 99th area percentile of the
    /// non-emitters' total radiosity, rounded up to a round number).
    float falseColourMaxW_m2 = 0.0f;
    /// Contour lines at each tick of the legend (false colour only).
    bool isolines = false;
    bool wireframe = false;
    /// Step mode: outline the last shooting patch, and tint the patches the shot changed
    /// visibly (unless most did; a gathering sweep tints nothing).
    bool highlightShooter = true;
    bool showLinks = false;       ///< hierarchical links as line segments
    bool showImportance = false;  ///< per-patch importance as a magenta tint
    /// ImGui text and spacing scale (projectors want 1.5-2); the lab applies it to its ImGuiLayer.
    float uiScale = 1.0f;
    /// Readouts also in photometric units (lx, cd/m^2) by Radiance's convention (Photometry.h).
    bool photometric = false;

    static constexpr int kLogDecades = 3;
};

} // namespace radiant::render
