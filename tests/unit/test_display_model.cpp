// The display model without GL (render/display): the exposure key's energy balance against the
// furnace's closed form and a two-surface enclosure, smoothing across near-coplanar faces but not
// creases, the false-colour legend's automatic range, tints and their atlas encoding, triangle
// winding for back-face culling, and the named shader variants. Expected values are written out here
// from the documented formulas, never taken from the model's own helpers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <set>
#include <vector>

#include "radiometry/common/Error.h"
#include "radiometry/scene/EnergyBalance.h"
#include "radiometry/scene/SceneLibrary.h"
#include "render/PatchShaderVariant.h"
#include "render/display/DisplayBuffers.h"
#include "render/display/DisplayModel.h"
#include "render/display/FaceGrids.h"
#include "render/display/PatchGeometry.h"
#include "render/display/SmoothingGroups.h"
#include "tests/support/Relative.h"

using namespace radiant;
using test::relativeTo;

namespace {

constexpr int kPatches = 5;

/// One surface, the unit square in z = 0 facing +z, cut into kPatches columns of equal area.
struct Field {
    Scene scene;
    PatchMesh mesh;

    explicit Field(const Material& material = {"grey", Rgb(0.5), ExitanceRgb{}}) {
        scene.name = "test field";
        scene.materials.push_back(material);
        Face face{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 1.0};
        scene.surfaces.push_back({"square", 0, {face}, "test"});
        for (int i = 0; i <= kPatches; ++i) {
            mesh.vertices.emplace_back(static_cast<double>(i) / kPatches, 0.0, 0.0);
            mesh.vertices.emplace_back(static_cast<double>(i) / kPatches, 1.0, 0.0);
        }
        for (std::uint32_t k = 0; k < kPatches; ++k) {
            Patch patch;
            patch.corners = {2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1};
            patch.cornerCount = 4;
            patch.area = 1.0 / kPatches;
            patch.centroid = {(k + 0.5) / kPatches, 0.5, 0.0};
            mesh.patches.push_back(patch);
        }
        mesh.surfaceFirstPatch = {0, kPatches};
    }
};

double acesOracle(double x) { return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
double srgbOracle(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

render::DisplaySettings flatPlain() {
    render::DisplaySettings settings;
    settings.highlightShooter = false;
    settings.shading = render::Shading::Flat;
    return settings;
}

/// Two triangles sharing the edge (0,0,0)-(1,1,0); the second folded about it by `foldDegrees`.
PatchMesh foldedPair(double foldDegrees) {
    PatchMesh mesh;
    const double a = foldDegrees * std::acos(-1.0) / 180.0;
    // The fold axis is the diagonal; the far corner (1, 0, 0) rotates about it out of the plane.
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 1, 0));
    const glm::dvec3 mid(0.5, 0.5, 0), offset = glm::dvec3(1, 0, 0) - mid;
    const glm::dvec3 rotated = mid + offset * std::cos(a) + glm::cross(axis, offset) * std::sin(a);
    mesh.vertices = {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, rotated};
    Patch first, second;
    first.corners = {0, 1, 2, 0};
    first.cornerCount = 3;
    first.normal = {0, 0, 1};
    first.area = 0.5;
    second.corners = {0, 3, 1, 0};
    second.cornerCount = 3;
    second.normal = glm::normalize(glm::cross(rotated - mesh.vertices[0], mesh.vertices[1] - mesh.vertices[0]));
    second.area = 0.5;
    mesh.patches = {first, second};
    mesh.surfaceFirstPatch = {0, 2};
    return mesh;
}

} // namespace

TEST_SUITE("display model") {

TEST_CASE("energy balance: the furnace settles at E / (1 - rho), an emitter and a reflector at rho P / sum A (1 - rho)") {
    Field furnace({"furnace", Rgb(0.5), ExitanceRgb(Rgb(2.0))});
    const std::vector<std::uint32_t> surfaces(kPatches, 0);
    const std::vector<double> areas(kPatches, 1.0 / kPatches);
    const EnergyBalance all = enclosureEnergyBalance(furnace.scene, surfaces, areas);
    CHECK(all.anythingEmits);
    CHECK(all.meanRadiosityW_m2.y == relativeTo(2.0 / (1 - 0.5), 1e-12));

    // A lamp of 1 m^2 (E = 10, rho = 0) and 4 m^2 of rho = 0.8: H = 10 / (1 + 4 * 0.2) = 5.555...,
    // the reflector leaves with 0.8 H.
    Scene room;
    room.name = "lamp and walls";
    room.materials = {{"lamp", Rgb(0.0), ExitanceRgb(Rgb(10.0))}, {"wall", Rgb(0.8), ExitanceRgb{}}};
    room.surfaces = {{"lamp", 0, {}, "test"}, {"wall", 1, {}, "test"}};
    const std::vector<std::uint32_t> which{0, 1, 1};
    const std::vector<double> area{1.0, 1.5, 2.5};
    const EnergyBalance balance = enclosureEnergyBalance(room, which, area);
    CHECK(balance.meanRadiosityW_m2.x == relativeTo(0.8 * 10.0 / (1.0 + 4.0 * 0.2), 1e-12));
    CHECK(luminanceOf(Rgb(1.0)) == relativeTo(1.0, 1e-12));

    const std::vector<std::uint32_t> bad{0, 7, 1};
    CHECK_THROWS_AS(enclosureEnergyBalance(room, bad, area), RadiantError);

    // Lit only by a point light of I = 2 W/sr: all 4 pi I is absorbed by 4 m^2 of rho = 0.8, so
    // H = 8 pi / (4 * 0.2) and the walls leave with 0.8 H.
    Scene lamp;
    lamp.name = "point light and walls";
    lamp.materials = {{"wall", Rgb(0.8), ExitanceRgb{}}};
    lamp.surfaces = {{"wall", 0, {}, "test"}};
    PunctualLight bulb;
    bulb.intensity = IntensityRgb(Rgb(2.0));
    lamp.lights.push_back(bulb);
    const std::vector<std::uint32_t> walls{0, 0};
    const std::vector<double> wallArea{1.5, 2.5};
    const EnergyBalance lit = enclosureEnergyBalance(lamp, walls, wallArea);
    CHECK(lit.anythingEmits);
    CHECK(lit.meanRadiosityW_m2.x == relativeTo(0.8 * 4 * std::numbers::pi * 2.0 / (4 * 0.2), 1e-12));
}

TEST_CASE("a light's power: a point's 4 pi I, a spot's cone by glTF's falloff, a sun's over the scene's mean projected area") {
    PunctualLight spot;
    spot.type = PunctualLightType::Spot;
    spot.intensity = IntensityRgb(Rgb(1.0));
    spot.innerConeAngle = 0.3;
    spot.outerConeAngle = 0.6;
    // The falloff integrated numerically over the cone (midpoint rule in the angle), as glTF defines it.
    double numeric = 0;
    constexpr int kSteps = 200000;
    for (int i = 0; i < kSteps; ++i) {
        const double a = (i + 0.5) * 0.6 / kSteps;
        const double t = std::clamp((std::cos(a) - std::cos(0.6)) / (std::cos(0.3) - std::cos(0.6)), 0.0, 1.0);
        numeric += 2 * std::numbers::pi * t * t * std::sin(a) * 0.6 / kSteps;
    }
    CHECK(lightPower(spot, 1.0).x == relativeTo(numeric, 1e-8));
    PunctualLight point;
    point.intensity = IntensityRgb(Rgb(3.0));
    CHECK(lightPower(point, 1.0).y == relativeTo(12 * std::numbers::pi, 1e-12));
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.normalIrradiance = IrradianceRgb(Rgb(100.0));
    CHECK(lightPower(sun, 8.0).z == relativeTo(200.0, 1e-12));
}

TEST_CASE("the exposure key: the furnace's E / (1 - rho) from the emitters, held while light spreads, or automatic") {
    const double exitance = 2.0, reflectance = 0.5, converged = exitance / (1 - reflectance);
    Field furnace({"furnace", Rgb(reflectance), ExitanceRgb(Rgb(exitance))});
    render::DisplayModel model;
    model.setMesh(furnace.scene, furnace.mesh);
    model.setSettings(flatPlain());
    // Early in the solve only the emission is there; the key already expects the converged light.
    CHECK(model.setRadiosity(std::vector<Rgb>(kPatches, Rgb(exitance)), 1, -1));
    CHECK(model.exposureKeyW_m2() == relativeTo(converged, 1e-12));
    REQUIRE(model.refreshColours());
    const double early = model.colours().patch[2].y;
    CHECK(std::abs(early - srgbOracle(acesOracle(exitance * 0.35 / converged))) < 1e-4);
    model.setRadiosity(std::vector<Rgb>(kPatches, Rgb(converged)), 2, -1);
    CHECK(model.exposureKeyW_m2() == relativeTo(converged, 1e-12));
    REQUIRE(model.refreshColours());
    CHECK(std::abs(model.colours().patch[2].y - srgbOracle(acesOracle(0.35))) < 1e-4);
    CHECK(model.colours().patch[2].y > early + 40.0 / 255);  // the view brightens as light spreads
    CHECK_FALSE(model.refreshColours());                     // nothing changed: nothing redone

    // A material edit keeps the key (doubling the light doubles what the picture shows); a new mesh
    // derives it again.
    Field brighter({"furnace", Rgb(reflectance), ExitanceRgb(Rgb(2 * exitance))});
    model.setMaterials(brighter.scene);
    CHECK(model.exposureKeyW_m2() == relativeTo(converged, 1e-12));
    model.setMesh(brighter.scene, brighter.mesh);
    CHECK(model.exposureKeyW_m2() == relativeTo(2 * converged, 1e-12));

    // Without emitters there is no balance: the automatic key, the mean luminance of the lit patches.
    Field field;
    render::DisplayModel grey;
    grey.setMesh(field.scene, field.mesh);
    std::vector<Rgb> rising;
    for (int k = 0; k < kPatches; ++k) rising.emplace_back(4.0 * k * k);
    grey.setRadiosity(rising, 1, -1);
    const double mean = (4.0 + 16 + 36 + 64) / 4;  // patch 0 is unlit
    CHECK(grey.exposureKeyW_m2() == relativeTo(mean, 1e-12));
    render::DisplaySettings settings = flatPlain();
    settings.exposureKey = render::ExposureKey::Held;
    grey.setSettings(settings);
    for (Rgb& b : rising) b *= 2.0;
    grey.setRadiosity(rising, 2, -1);
    CHECK(grey.exposureKeyW_m2() == relativeTo(mean, 1e-12));
    CHECK(grey.automaticExposureKeyW_m2() == relativeTo(2 * mean, 1e-12));
    ++settings.rekeyCount;
    grey.setSettings(settings);
    CHECK(grey.exposureKeyW_m2() == relativeTo(2 * mean, 1e-12));
    settings.exposureStops = 1.0f;
    grey.setSettings(settings);
    CHECK(grey.exposureScale() == relativeTo(2 * 0.35 / (2 * mean), 1e-12));

    CHECK_FALSE(grey.setRadiosity(rising, 2, -1));  // the same generation is skipped
    CHECK_THROWS_AS(grey.setRadiosity(std::vector<Rgb>(kPatches - 1, Rgb(1.0)), 3, -1), RadiantError);
}

TEST_CASE("smoothing: vertex radiosity is the area-weighted mean across faces a few degrees apart, not across creases") {
    // The field: vertex radiosity at column i is the mean of its (equal-area) neighbours.
    Field field;
    render::DisplayModel model;
    model.setMesh(field.scene, field.mesh);
    model.setRadiosity(std::vector<Rgb>{Rgb(0), Rgb(4), Rgb(16), Rgb(36), Rgb(64)}, 1, -1);
    const render::SmoothingGroups& groups = model.smoothing();
    CHECK(groups.vertexCount == field.mesh.vertices.size());
    // Patch 2's corner 0 is at x = 0.4, between patches 1 (4) and 2 (16).
    CHECK(model.smoothRadiosity()[groups.cornerVertex[2][0]].x == relativeTo(10.0, 1e-12));

    // Two triangles folded 2 degrees about their shared edge share its two vertices' radiosity;
    // folded 90 degrees (a block's edge) they do not.
    const render::SmoothingGroups slight = render::findSmoothingGroups(foldedPair(2.0));
    CHECK(slight.vertexCount == 4);
    CHECK(slight.cornerVertex[0][0] == slight.cornerVertex[1][0]);
    CHECK(slight.cornerVertex[0][1] == slight.cornerVertex[1][2]);
    const render::SmoothingGroups crease = render::findSmoothingGroups(foldedPair(90.0));
    CHECK(crease.vertexCount == 6);
    CHECK(crease.cornerVertex[0][0] != crease.cornerVertex[1][0]);
    std::vector<Rgb> smoothed;
    render::smoothRadiosity(slight, std::vector<double>{0.5, 1.5}, std::vector<Rgb>{Rgb(2.0), Rgb(6.0)}, smoothed);
    CHECK(smoothed[slight.cornerVertex[0][0]].z == relativeTo((0.5 * 2 + 1.5 * 6) / 2.0, 1e-12));
    CHECK(smoothed[slight.cornerVertex[0][2]].z == relativeTo(2.0, 1e-12));

    // The Cornell box's left (red) wall: two slightly non-planar triangles, meshed as one surface.
    // Every mesh vertex of the wall carries one smoothed radiosity, so no seam follows its diagonal.
    const Scene cornell = loadScene("cornell-box").scene;
    const PatchMesh mesh = meshScene(cornell, {0.01});
    const render::SmoothingGroups cornellGroups = render::findSmoothingGroups(mesh);
    const std::size_t leftWall = cornell.findSurface("left wall");
    REQUIRE(leftWall != Scene::npos);
    std::set<std::uint32_t> meshVertices, smoothingVertices;
    std::set<std::uint32_t> faces;
    for (std::size_t p = mesh.surfaceFirstPatch[leftWall]; p < mesh.surfaceFirstPatch[leftWall + 1]; ++p) {
        faces.insert(mesh.patches[p].face);
        for (std::uint8_t c = 0; c < mesh.patches[p].cornerCount; ++c) {
            meshVertices.insert(mesh.patches[p].corners[c]);
            smoothingVertices.insert(cornellGroups.cornerVertex[p][c]);
        }
    }
    CHECK(faces.size() == 2);
    CHECK(smoothingVertices.size() == meshVertices.size());
    // Grouped by exact normals (a hundredth of a degree), the diagonal's vertices split in two: the seam.
    const render::SmoothingGroups exact = render::findSmoothingGroups(mesh, 0.01);
    std::set<std::uint32_t> exactVertices;
    for (std::size_t p = mesh.surfaceFirstPatch[leftWall]; p < mesh.surfaceFirstPatch[leftWall + 1]; ++p)
        for (std::uint8_t c = 0; c < mesh.patches[p].cornerCount; ++c) exactVertices.insert(exact.cornerVertex[p][c]);
    CHECK(exactVertices.size() > meshVertices.size());
    // The short block's sides meet at right angles: its corners keep one value per side.
    const std::size_t block = cornell.findSurface("short block");
    REQUIRE(block != Scene::npos);
    std::set<std::uint32_t> blockMesh, blockSmoothing;
    for (std::size_t p = mesh.surfaceFirstPatch[block]; p < mesh.surfaceFirstPatch[block + 1]; ++p)
        for (std::uint8_t c = 0; c < mesh.patches[p].cornerCount; ++c) {
            blockMesh.insert(mesh.patches[p].corners[c]);
            blockSmoothing.insert(cornellGroups.cornerVertex[p][c]);
        }
    CHECK(blockSmoothing.size() > blockMesh.size());
}

TEST_CASE("legend: the automatic range is the reflectors' 99th area percentile rounded up, and one hot patch does not stretch it") {
    // 100 equal reflector patches with totals 1 .. 100 W/m^2, the last one a hot spot of 1e6.
    Scene scene;
    scene.name = "strip";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb{}});
    scene.surfaces.push_back({"strip", 0, {}, "test"});
    PatchMesh mesh;
    std::vector<Rgb> radiosity;
    for (std::uint32_t k = 0; k < 100; ++k) {
        mesh.vertices.emplace_back(k, 0, 0);
        Patch patch;
        patch.corners = {k, k, k, k};
        patch.cornerCount = 3;
        patch.area = 1.0;
        mesh.patches.push_back(patch);
        radiosity.emplace_back(k == 99 ? 1e6 : (k + 1.0) / 3, (k + 1.0) / 3, (k + 1.0) / 3);
    }
    mesh.surfaceFirstPatch = {0, 100};
    render::DisplayModel model;
    model.setMesh(scene, mesh);
    model.setRadiosity(radiosity, 1, -1);
    render::DisplaySettings settings;
    settings.colourMode = render::ColourMode::FalseColour;
    model.setSettings(settings);
    // The 99th patch by area is total 99: rounded up to the next of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k.
    CHECK(model.legend().maxW_m2 == relativeTo(100.0, 1e-12));
    settings.falseColourMaxW_m2 = 40.0f;
    model.setSettings(settings);
    CHECK(model.legend().maxW_m2 == relativeTo(40.0, 1e-12));
    REQUIRE(model.refreshColours());
    CHECK(model.colours().falseColour);
    // Patch 9 has total 10 W/m^2: a quarter of the way up the 0 .. 40 colour map.
    const render::SmoothingGroups& groups = model.smoothing();
    CHECK(model.colours().vertex[groups.cornerVertex[9][0]].w == doctest::Approx(0.25).epsilon(1e-6));

    const render::ColourLegend linear = render::makeLegend(37.0, false, 3);
    CHECK(linear.minW_m2 == 0.0);
    REQUIRE(linear.ticksW_m2.size() >= 4);
    CHECK(linear.ticksW_m2.front() == 0.0);
    CHECK(linear.ticksW_m2[1] == relativeTo(5.0, 1e-12));
    CHECK(linear.ticksW_m2.back() <= 37.0);
    CHECK(linear.position(37.0 / 4) == relativeTo(0.25, 1e-12));
    const render::ColourLegend log = render::makeLegend(250.0, true, 3);
    CHECK(log.minW_m2 == relativeTo(0.25, 1e-12));
    REQUIRE(log.ticksW_m2.size() == 9);  // 0.5, 1, 2, 5, ..., 200 (tests/unit/test_legend.cpp)
    CHECK(log.ticksW_m2[1] == relativeTo(1.0, 1e-12));
    CHECK(log.ticksW_m2[7] == relativeTo(100.0, 1e-12));
    CHECK(log.position(std::sqrt(0.25 * 250.0)) == relativeTo(0.5, 1e-12));
}

TEST_CASE("tints: successive mixes combine into one, the shooter is outlined and what it changed tinted, a gathering sweep tints none") {
    // mix(mix(c, a, a.w), b, b.w) == mix(c, combined, combined.w) for any colour c.
    const render::Tint a{1.0f, 0.1f, 0.8f, 0.3f}, b{1.0f, 0.45f, 0.0f, 0.35f};
    const render::Tint both = render::addTint(a, b);
    for (const glm::vec3 c : {glm::vec3(0.0f), glm::vec3(0.2f, 0.7f, 0.4f), glm::vec3(1.0f)}) {
        const glm::vec3 twice = glm::mix(glm::mix(c, glm::vec3(a), a.w), glm::vec3(b), b.w);
        const glm::vec3 once = glm::mix(c, glm::vec3(both), both.w);
        CHECK(glm::distance(twice, once) < 1e-6f);
    }
    CHECK(render::addTint(render::Tint(0.0f), render::Tint(0.0f)).w == 0.0f);
    // The atlas's 8-bit alpha: amount / 2, + 1/2 when outlined.
    CHECK(render::tintTexel({1, 0, 0, 0.4f}).w == doctest::Approx(0.2f));
    CHECK(render::tintTexel({1, 0, 0, 2.4f}).w == doctest::Approx(0.7f));

    Field field;
    render::DisplayModel model;
    model.setMesh(field.scene, field.mesh);
    render::DisplaySettings settings;  // highlightShooter on by default
    settings.shading = render::Shading::Flat;
    model.setSettings(settings);
    std::vector<Rgb> radiosity(kPatches, Rgb(1.0));
    model.setRadiosity(radiosity, 1, 3);
    model.refreshColours();
    CHECK(model.colours().tint[3].w >= 2.0f);  // the shooter: outlined
    CHECK(model.colours().tint[1].w == 0.0f);
    CHECK(model.colours().anyTint);
    radiosity[0] = Rgb(2.0);  // a shot from patch 4 changed patch 0 visibly
    model.setRadiosity(radiosity, 2, 4);
    model.refreshColours();
    CHECK(model.colours().tint[0].w == doctest::Approx(0.22f));
    CHECK(model.colours().tint[1].w == 0.0f);
    for (Rgb& r : radiosity) r *= 3.0;  // every patch changed: a sweep
    model.setRadiosity(radiosity, 3, -1);
    model.refreshColours();
    CHECK_FALSE(model.colours().anyTint);
    // A late gathering sweep changes a few patches visibly: no tint either. Tinting them left an
    // orange staircase (the sweep's front) on the Cornell box's converged ceiling.
    radiosity[2] *= 1.5;
    model.setRadiosity(radiosity, 4, -1);
    model.refreshColours();
    CHECK_FALSE(model.colours().anyTint);
}

TEST_CASE("geometry: every drawn triangle and grid quad is wound counter-clockwise about its patch's normal") {
    const Scene cornell = loadScene("cornell-box").scene;
    const PatchMesh mesh = meshScene(cornell, {0.02});
    const render::FaceGrids grids = render::findFaceGrids(cornell, mesh);
    const render::SmoothingGroups smoothing = render::findSmoothingGroups(mesh);
    const render::PatchTriangles triangles = render::patchTriangles(mesh, grids, smoothing);
    REQUIRE_FALSE(triangles.vertices.empty());
    for (std::size_t v = 0; v + 2 < triangles.vertices.size(); v += 3) {
        const glm::vec3 e1 = triangles.vertices[v + 1].position - triangles.vertices[v].position;
        const glm::vec3 e2 = triangles.vertices[v + 2].position - triangles.vertices[v].position;
        CHECK(glm::dot(glm::cross(e1, e2), triangles.vertices[v].normal) > 0.0f);
    }
    // The indexed draw's triangles are these, corner for corner, each patch's corners stored once.
    REQUIRE(triangles.cornerIndices.size() == triangles.vertices.size());
    std::size_t drawnPatches = 0, drawnCorners = 0;
    for (std::size_t p = 0; p < mesh.size(); ++p)
        if (!grids.patchInGrid[p]) {
            ++drawnPatches;
            drawnCorners += mesh.patches[p].cornerCount;
        }
    CHECK(triangles.corners.size() == drawnCorners);
    CHECK(triangles.corners.size() < triangles.vertices.size());  // quads' corners are shared by their two triangles
    for (std::size_t v = 0; v < triangles.vertices.size(); ++v) {
        const std::uint32_t c = triangles.cornerIndices[v];
        REQUIRE(c < triangles.corners.size());
        CHECK(triangles.corners[c].position == triangles.vertices[v].position);
        CHECK(triangles.corners[c].normal == triangles.vertices[v].normal);
        CHECK(triangles.cornerPatch[c] == triangles.drawnPatch[v]);
        CHECK(triangles.cornerSmoothing[c] == triangles.drawnSmoothing[v]);
    }
    CHECK(drawnPatches > 0);
    const std::vector<render::GridVertex> quads = render::gridQuads(grids);
    REQUIRE(quads.size() == 6 * grids.grids.size());
    for (std::size_t v = 0; v < quads.size(); v += 3) {
        const glm::vec3 e1 = quads[v + 1].position - quads[v].position, e2 = quads[v + 2].position - quads[v].position;
        CHECK(glm::dot(glm::cross(e1, e2), quads[v].normal) > 0.0f);
    }
    const std::array<render::GridVertex, 6> cell = render::gridCellQuad(grids.grids.front(), 0);
    CHECK(glm::dot(glm::cross(cell[1].position - cell[0].position, cell[2].position - cell[0].position), cell[0].normal) > 0.0f);
}

TEST_CASE("face grids: a meshed quad face is found as its n x m grid, cell (i, j) centred at the bilinear point") {
    // A trapezoid (not a parallelogram), so the bilinear map is not affine.
    Scene scene;
    scene.name = "trapezoid";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb{}});
    Face face;
    face.vertices = {{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}};
    face.updateGeometry();
    scene.surfaces.push_back({"trapezoid", 0, {face}, "test"});
    const PatchMesh mesh = meshScene(scene, {face.area / 12.0});
    const render::FaceGrids found = render::findFaceGrids(scene, mesh);
    REQUIRE(found.grids.size() == 1);
    const render::FaceGrid& grid = found.grids.front();
    CHECK(static_cast<std::size_t>(grid.columns) * grid.rows == mesh.size());
    CHECK(grid.columns > 1);
    CHECK(grid.rows > 1);
    for (std::size_t j = 0; j < grid.rows; ++j)
        for (std::size_t i = 0; i < grid.columns; ++i) {
            const double u = (static_cast<double>(i) + 0.5) / grid.columns, v = (static_cast<double>(j) + 0.5) / grid.rows;
            const glm::dvec3 bilinear = (1 - u) * (1 - v) * face.vertices[0] + u * (1 - v) * face.vertices[1] +
                                        u * v * face.vertices[2] + (1 - u) * v * face.vertices[3];
            const Patch& patch = mesh.patches[grid.cellPatch[j * grid.columns + i]];
            glm::dvec3 centre(0.0);
            for (int c = 0; c < 4; ++c) centre += mesh.vertices[patch.corners[static_cast<std::size_t>(c)]] / 4.0;
            CAPTURE(i);
            CAPTURE(j);
            CHECK(glm::distance(centre, bilinear) < 1e-9);
        }

    // The Cornell box: every quad face is a grid but the floor cut along the blocks; the left wall, two triangles, is not.
    const Scene cornell = loadScene("cornell-box").scene;
    const PatchMesh cornellMesh = meshScene(cornell, {0.01});
    const render::FaceGrids cornellGrids = render::findFaceGrids(cornell, cornellMesh);
    const std::size_t leftWall = cornell.findSurface("left wall");
    REQUIRE(leftWall != Scene::npos);
    for (std::size_t p = 0; p < cornellMesh.size(); ++p) {
        const Patch& patch = cornellMesh.patches[p];
        // The floor is cut along the blocks' footprints (ContactCuts.h) into pieces, no grid.
        const bool quadFace = cornell.surfaces[patch.surface].faces[patch.face].vertices.size() == 4 &&
                              cornell.surfaces[patch.surface].name != "floor";
        CAPTURE(p);
        CHECK(static_cast<bool>(cornellGrids.patchInGrid[p]) == quadFace);
        if (patch.surface == leftWall) CHECK_FALSE(cornellGrids.patchInGrid[p]);
    }
}

TEST_CASE("shader variants: each combination has its own index and names its defines") {
    std::set<std::size_t> indices;
    for (unsigned bits = 0; bits < render::PatchShaderVariant::kCount; ++bits) {
        const render::PatchShaderVariant v{(bits & 1u) != 0, (bits & 2u) != 0, (bits & 4u) != 0,
                                           (bits & 8u) != 0, (bits & 16u) != 0, (bits & 32u) != 0};
        CHECK(v.index() < render::PatchShaderVariant::kCount);
        indices.insert(v.index());
    }
    CHECK(indices.size() == render::PatchShaderVariant::kCount);
    render::PatchShaderVariant falseColourEdges;
    falseColourEdges.falseColour = true;
    falseColourEdges.edges = true;
    CHECK(falseColourEdges.defines() == "#define FALSE_COLOUR 1\n#define EDGES 1\n");
    CHECK(render::PatchShaderVariant{}.defines().empty());
}

}  // TEST_SUITE
