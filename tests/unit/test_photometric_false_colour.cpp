// False colour with photometric units: the illuminance each patch receives, in lx, read from the
// solution by the radiosity equation backwards (E = (B - M) / rho per band) and converted as
// 179 lm/W x (0.265 R + 0.670 G + 0.065 B). Expected values are worked out here from those formulas.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "render/display/DisplayModel.h"
#include "tests/support/Relative.h"

using namespace radiant;
using test::relativeTo;

namespace {

/// Two patches side by side on one square surface of `material`.
struct TwoPatches {
    Scene scene;
    PatchMesh mesh;
    explicit TwoPatches(const Material& material) {
        scene.name = "two patches";
        scene.materials.push_back(material);
        Face face{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 2.0};
        scene.surfaces.push_back({"square", 0, {face}, "test"});
        for (int i = 0; i <= 2; ++i) {
            mesh.vertices.emplace_back(i, 0.0, 0.0);
            mesh.vertices.emplace_back(i, 1.0, 0.0);
        }
        for (std::uint32_t k = 0; k < 2; ++k) {
            Patch patch;
            patch.corners = {2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1};
            patch.cornerCount = 4;
            patch.area = 1.0;
            patch.centroid = {k + 0.5, 0.5, 0.0};
            mesh.patches.push_back(patch);
        }
        mesh.surfaceFirstPatch = {0, 2};
    }
};

render::DisplaySettings photometricFalseColour(float maxLux) {
    render::DisplaySettings settings;
    settings.highlightShooter = false;
    settings.shading = render::Shading::Flat;
    settings.colourMode = render::ColourMode::FalseColour;
    settings.photometric = true;
    settings.falseColourMaxW_m2 = maxLux;
    return settings;
}

double lux(const Rgb& irradiance) { return 179.0 * (0.265 * irradiance.x + 0.670 * irradiance.y + 0.065 * irradiance.z); }

} // namespace

TEST_CASE("photometric false colour maps each patch's illuminance in lx, the emitter's own light left out") {
    const Rgb rho(0.5, 0.4, 0.2), exitance(30.0, 20.0, 10.0);
    TwoPatches field(Material{"lit lamp", rho, ExitanceRgb(exitance)});
    const Rgb e0(10.0, 10.0, 10.0), e1(1.0, 2.0, 3.0);  // W/m^2 arriving at each patch
    const std::vector<Rgb> radiosity{exitance + rho * e0, exitance + rho * e1};
    render::DisplayModel model;
    model.setMesh(field.scene, field.mesh);
    model.setRadiosity(radiosity, 1, -1);
    model.setSettings(photometricFalseColour(2000.0f));
    const render::ColourLegend legend = model.legend();
    CHECK(std::string(legend.unit) == "lx");
    CHECK(std::string(legend.quantity) == "illuminance");
    CHECK(legend.maxW_m2 == relativeTo(2000.0, 1e-12));
    REQUIRE(model.refreshColours());
    CHECK(lux(e0) == relativeTo(1790.0, 1e-12));
    CHECK(model.colours().patch[0].w == doctest::Approx(lux(e0) / 2000.0).epsilon(1e-6).scale(0));
    CHECK(model.colours().patch[1].w == doctest::Approx(lux(e1) / 2000.0).epsilon(1e-6).scale(0));
    CHECK(model.colours().tint[0].w == 0.0f);

    // The automatic range: the 99th area percentile of the reflectors, here none (it emits), so the
    // brightest patch's 1790 lx rounded up to 2000.
    model.setSettings(photometricFalseColour(0.0f));
    CHECK(model.legend().maxW_m2 == relativeTo(2000.0, 1e-12));

    // Radiometric again: total radiosity in W/m^2.
    render::DisplaySettings radiometric = photometricFalseColour(100.0f);
    radiometric.photometric = false;
    model.setSettings(radiometric);
    CHECK(std::string(model.legend().unit) == "W/m^2");
    REQUIRE(model.refreshColours());
    const double total0 = radiosity[0].x + radiosity[0].y + radiosity[0].z;
    CHECK(model.colours().patch[0].w == doctest::Approx(total0 / 100.0).epsilon(1e-6).scale(0));
}

TEST_CASE("photometric false colour greys a surface black in a band: its radiosity says nothing of the light there") {
    TwoPatches field(Material{"no blue", Rgb(0.5, 0.5, 0.0), ExitanceRgb{}});
    const std::vector<Rgb> radiosity{Rgb(5.0, 5.0, 0.0), Rgb(1.0, 1.0, 0.0)};
    render::DisplayModel model;
    model.setMesh(field.scene, field.mesh);
    model.setRadiosity(radiosity, 1, -1);
    model.setSettings(photometricFalseColour(100.0f));
    REQUIRE(model.refreshColours());
    for (std::size_t p = 0; p < 2; ++p) {
        CHECK(model.colours().tint[p].w > 0.9f);
        CHECK(model.colours().tint[p].x == doctest::Approx(model.colours().tint[p].z));  // grey
    }
    // In W/m^2 the same surface has a colour-map colour and no tint.
    render::DisplaySettings radiometric = photometricFalseColour(100.0f);
    radiometric.photometric = false;
    model.setSettings(radiometric);
    REQUIRE(model.refreshColours());
    CHECK(model.colours().tint[0].w == 0.0f);
    CHECK(model.colours().patch[0].w == doctest::Approx(0.1).epsilon(1e-6).scale(0));
}
