#pragma once
// The features a variant of shaders/patch.*.glsl is compiled with, by name (as polyscope's shader
// rules): software GL runs shaders on the CPU, so each variant pays per pixel only for what is
// shown. GL-free.
#include <cstddef>
#include <string>

namespace radiant::render {

struct PatchShaderVariant {
    bool lightMap = false;     ///< LIGHT_MAP: a grid face drawn as one quad from its atlases (else triangles)
    bool flat = false;         ///< FLAT: light maps fetch patch colours rather than interpolate vertices
    bool tints = false;        ///< TINTS: light maps read the tint atlas (some patch is tinted)
    bool falseColour = false;  ///< FALSE_COLOUR: viridis of the colour-map position
    bool isolines = false;     ///< ISOLINES: contour lines at the legend's ticks (with false colour)
    bool edges = false;        ///< EDGES: wireframe and the shooter's outline

    bool operator==(const PatchShaderVariant&) const = default;

    static constexpr std::size_t kCount = 64;
    /// A distinct number in [0, kCount) per variant, for a table of compiled programs.
    [[nodiscard]] constexpr std::size_t index() const {
        return (lightMap ? 1u : 0u) | (flat ? 2u : 0u) | (tints ? 4u : 0u) | (falseColour ? 8u : 0u) |
               (isolines ? 16u : 0u) | (edges ? 32u : 0u);
    }
    /// "#define NAME 1\n" for each feature on, as ShaderProgram inserts after #version.
    [[nodiscard]] std::string defines() const {
        std::string text;
        const auto define = [&](bool on, const char* name) {
            if (on) text += std::string("#define ") + name + " 1\n";
        };
        define(lightMap, "LIGHT_MAP");
        define(flat, "FLAT");
        define(tints, "TINTS");
        define(falseColour, "FALSE_COLOUR");
        define(isolines, "ISOLINES");
        define(edges, "EDGES");
        return text;
    }
};

} // namespace radiant::render
