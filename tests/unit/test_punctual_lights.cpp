// glTF's KHR_lights_punctual lights as sources in every method (tests/data/make_light_scenes.py):
// the lecture's point source E = I cos(theta) / r^2, a spot's cone, a sun's E cos(theta) with its
// shadow, the candela and lux conversion at 179 lm/W, and the refusal of a scene nothing lights.
// Closed forms: a black room (the probe reads the light alone), a room whose only reflector is the
// floor (its power is rho I Omega, Omega the floor's solid angle from the bulb, the corner-rectangle
// formula of docs/reference.md), and a closed grey room (all of the bulb's 4 pi I is absorbed, so
// sum A B = rho / (1 - rho) 4 pi I); the grey room is also checked against the reference tracer.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/GltfLoader.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/units/Photometry.h"
#include "tests/support/Relative.h"
#include "tests/support/RunRadiant.h"
#include "tests/support/Common.h"
#include "tests/support/CatalogViewFactors.h"

using namespace radiant;
using radiant::test::relativeTo;
namespace fs = std::filesystem;

namespace {

std::string lightFile(const std::string& name) { return std::string(RADIANT_TEST_DATA_DIR) + "/lights/" + name; }

constexpr std::array kLightMethods{SolverMethod::Jacobi, SolverMethod::GaussSeidel, SolverMethod::Progressive,
                              SolverMethod::Hierarchical, SolverMethod::Importance};

// The rooms' bulb: 179 cd of white light, 1 W/sr per band, at (0.5, 2, 0).
constexpr double kBulbIntensity = 1.0;
const glm::dvec3 kBulb{0.5, 2, 0};

/// Solid angle of an a x b rectangle seen from height h above one corner (docs/reference.md).
using radiant::test::cornerRectangleSolidAngle;

/// The room's 4 m x 4 m floor from the bulb: four rectangles meeting below it.
double floorSolidAngleFromBulb() {
    return 2 * cornerRectangleSolidAngle(2.5, 2, 2) + 2 * cornerRectangleSolidAngle(1.5, 2, 2);
}

/// I cos(theta) / r^2 at x facing n, from the lecture's formula, not the code's.
double pointSourceE(double intensity, const glm::dvec3& source, const glm::dvec3& x, const glm::dvec3& n) {
    const glm::dvec3 d = source - x;
    const double r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return intensity * (d.x * n.x + d.y * n.y + d.z * n.z) / r / (r * r);
}

struct Solution {
    Scene scene;
    PatchMesh mesh;
    std::vector<Rgb> B;

    [[nodiscard]] double power(std::size_t surface) const {
        double sum = 0;
        for (std::size_t i = mesh.surfaceFirstPatch[surface]; i < mesh.surfaceFirstPatch[surface + 1]; ++i)
            sum += mesh.patches[i].area * B[i].y;
        return sum;
    }
    [[nodiscard]] double totalPower() const {
        double sum = 0;
        for (std::size_t s = 0; s < scene.surfaces.size(); ++s) sum += power(s);
        return sum;
    }
    [[nodiscard]] ProbeReading probe(const glm::dvec3& x, const glm::dvec3& n) const {
        const RayCaster rays(scene);
        const Probe p(scene, mesh, &rays);
        return p.measure(x, n, B);
    }
};

Solution solveLitScene(const std::string& file, SolverMethod method, double maxPatchArea = 0.25) {
    Solution s{loadScene(lightFile(file)).scene, {}, {}};
    s.mesh = meshScene(s.scene, MeshingOptions{maxPatchArea});
    const auto solver = makeSolver(method, s.scene, s.mesh);
    for (int k = 0; k < 100000; ++k) {  // progressive: one shot per step
        const IterationStats stats = solver->step();
        if (stats.residual <= 1e-6 && stats.linksRefined == 0) break;
    }
    CHECK(solver->lastStats().residual <= 1e-6);
    s.B = solver->solution();
    return s;
}

using Run = test::CommandRun;
using test::runRadiant;

using radiant::test::contains;

/// The black room's glTF with `edit` applied, loaded from memory (its buffers are data: URIs).
template <class Edit>
LoadedScene loadEdited(Edit&& edit) {
    std::ifstream in(lightFile("point_black_room.gltf"));
    nlohmann::json doc = nlohmann::json::parse(in);
    edit(doc);
    const std::string text = doc.dump();
    return loadGltfFromMemory({reinterpret_cast<const unsigned char*>(text.data()), text.size()}, "edited.gltf");
}

/// The one-line error loading the edited file gives; empty when it loads.
template <class Edit>
std::string editedLoadError(Edit&& edit) {
    try {
        (void)loadEdited(std::forward<Edit>(edit));
    } catch (const RadiantError& error) {
        return error.what();
    }
    return {};
}

using radiant::test::anyContains;

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("Radiance's photometric convention: 179 lm/W and Y = 0.265 R + 0.670 G + 0.065 B") {
    CHECK(luminanceWeighted(Rgb(1.0)) == relativeTo(1.0, 1e-12));
    CHECK(illuminanceLux(IrradianceRgb(Rgb(1.0))) == relativeTo(179.0, 1e-12));
    CHECK(illuminanceLux(IrradianceRgb(Rgb(2, 1, 4))) == relativeTo(179 * (0.265 * 2 + 0.670 * 1 + 0.065 * 4), 1e-12));
    CHECK(luminanceCdPerM2(RadianceRgb(Rgb(0, 1, 0))) == relativeTo(179 * 0.670, 1e-12));
    CHECK(luminousFluxLumen(PowerRgb(Rgb(0, 0, 1))) == relativeTo(179 * 0.065, 1e-12));
    // A coloured light keeps its luminous amount: 100 cd of (1, 0.5, 0.25) is 100 cd.
    const Rgb bands = bandsForLuminous(100, Rgb(1, 0.5, 0.25));
    CHECK(luminousIntensityCandela(IntensityRgb(bands)) == relativeTo(100.0, 1e-12));
    CHECK(bands.y / bands.x == relativeTo(0.5, 1e-12));
}

TEST_CASE("the loader reads point, spot and directional lights in SI units from candela and lux") {
    const Scene room = loadGltf(lightFile("point_black_room.gltf")).scene;
    REQUIRE(room.lights.size() == 1);
    const PunctualLight& bulb = room.lights[0];
    CHECK(bulb.name == "Bulb");
    CHECK(bulb.type == PunctualLightType::Point);
    CHECK(bulb.position.x == relativeTo(0.5, 1e-12));
    CHECK(bulb.position.y == relativeTo(2.0, 1e-12));
    for (int band = 0; band < 3; ++band) CHECK(bulb.intensity.value()[band] == relativeTo(kBulbIntensity, 1e-12));

    const Scene spot = loadGltf(lightFile("spot_floor.gltf")).scene;
    REQUIRE(spot.lights.size() == 1);
    CHECK(spot.lights[0].type == PunctualLightType::Spot);
    CHECK(spot.lights[0].direction.y == relativeTo(-1.0, 1e-9));
    CHECK(std::abs(spot.lights[0].direction.x) < 1e-9);
    CHECK(spot.lights[0].innerConeAngle == relativeTo(0.3, 1e-12));
    CHECK(spot.lights[0].outerConeAngle == relativeTo(0.5, 1e-12));

    const Scene sun = loadGltf(lightFile("sun_floor.gltf")).scene;
    REQUIRE(sun.lights.size() == 1);
    CHECK(sun.lights[0].type == PunctualLightType::Directional);
    CHECK(sun.lights[0].direction.x == relativeTo(-std::sin(std::numbers::pi / 3), 1e-9));
    CHECK(sun.lights[0].direction.y == relativeTo(-0.5, 1e-9));
    CHECK(sun.lights[0].normalIrradiance.value().x == relativeTo(1000.0 / 179.0, 1e-12));
}

TEST_CASE("a bad light is refused in one line naming it, and one that gives no light or is placed nowhere is a warning") {
    const auto light = [](nlohmann::json& doc) -> nlohmann::json& { return doc["extensions"]["KHR_lights_punctual"]["lights"][0]; };
    const auto refused = [](const std::string& message, const std::string& part) {
        CAPTURE(message);
        CHECK(contains(message, "edited.gltf: "));
        CHECK(contains(message, part));
        CHECK(!contains(message, "\n"));
    };
    refused(editedLoadError([&](nlohmann::json& d) { light(d)["intensity"] = -1; }), "light 0 'Bulb': intensity -1 must be a finite value >= 0 (cd)");
    refused(editedLoadError([&](nlohmann::json& d) { light(d)["color"] = {1, 1}; }), "light 0 'Bulb': color has 2 values, expected 3");
    refused(editedLoadError([&](nlohmann::json& d) { light(d)["color"] = {1, -0.5, 1}; }), "color band 1 is -0.5, expected >= 0");
    refused(editedLoadError([&](nlohmann::json& d) {
                light(d)["type"] = "spot";
                light(d)["spot"] = {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}};
            }),
            "spot cone angles inner 0.6 and outer 0.5 rad must satisfy 0 <= inner < outer <= pi/2");
    refused(editedLoadError([](nlohmann::json& d) { d["nodes"].back()["extensions"]["KHR_lights_punctual"]["light"] = 3; }),
            "KHR_lights_punctual light 3 out of range (light count 1)");

    const LoadedScene dark = loadEdited([&](nlohmann::json& d) { light(d)["intensity"] = 0; });
    CHECK(dark.scene.lights.empty());
    CHECK(dark.ignoredLights == 1);
    CHECK(anyContains(dark.warnings, "light 0 'Bulb': gives no light"));
    const LoadedScene unplaced = loadEdited([](nlohmann::json& d) { d["nodes"].back().erase("extensions"); });
    CHECK(unplaced.scene.lights.empty());
    CHECK(anyContains(unplaced.warnings, "light 0 'Bulb' (KHR_lights_punctual) is placed by no node of the scene; ignored"));
    const LoadedScene ranged = loadEdited([&](nlohmann::json& d) { light(d)["range"] = 5; });
    CHECK(ranged.scene.lights.size() == 1);
    CHECK(anyContains(ranged.warnings, "range 5 m ignored"));
    const LoadedScene area = loadEdited([&](nlohmann::json& d) { light(d)["type"] = "area"; });
    CHECK(area.scene.lights.empty());
    CHECK(anyContains(area.warnings, "type 'area' is not point, spot or directional; light ignored"));
}

TEST_CASE("a Blender point lamp's 'watt' arrives as 683/179 W of white light") {
    // Blender's exporter wrote 1 W as 683 / (4 pi) cd = 54.35 cd (tests/data/make_blender_scenes.py).
    const Scene scene = loadScene(std::string(RADIANT_TEST_DATA_DIR) + "/blender/point_lamp_only.gltf").scene;
    REQUIRE(scene.lights.size() == 1);
    const double power = 4 * std::numbers::pi * scene.lights[0].intensity.value().x;
    CHECK(power == relativeTo(683.0 / 179.0, 1e-6));
    // On the floor 2 m below: I / d^2 in lx.
    const PatchMesh mesh = meshScene(scene, MeshingOptions{0.25});
    const RayCaster rays(scene);
    const Probe probe(scene, mesh, &rays);
    const std::vector<Rgb> dark(mesh.size(), Rgb(0.0));
    const ProbeReading reading = probe.measure(glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0), dark);
    CHECK(illuminanceLux(reading.directIrradiance) == relativeTo(54.35141306588226 / 4, 1e-6));
}

TEST_CASE("a black room lit by a point light: every method's probe reads E = I cos(theta) / r^2") {
    for (const SolverMethod method : kLightMethods) {
        CAPTURE(methodName(method));
        const Solution s = solveLitScene("point_black_room.gltf", method);
        CHECK(s.totalPower() == 0.0);  // nothing reflects
        for (const auto& at : {std::pair{glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0)},
                               std::pair{glm::dvec3(-1, 0, 1), glm::dvec3(0, 1, 0)},
                               std::pair{glm::dvec3(-2, 1.5, 0.5), glm::dvec3(1, 0, 0)},
                               std::pair{glm::dvec3(1, 3, -1), glm::dvec3(0, -1, 0)}}) {
            const glm::dvec3 x = at.first, n = at.second;
            CAPTURE(x);
            const ProbeReading reading = s.probe(x, n);
            const double expected = pointSourceE(kBulbIntensity, kBulb, x, n);
            for (int band = 0; band < 3; ++band) {
                CHECK(reading.irradiance.value()[band] == relativeTo(expected, 1e-9));
                CHECK(reading.directIrradiance.value()[band] == relativeTo(expected, 1e-9));
            }
        }
    }
}

TEST_CASE("only the floor reflects: every method gives it rho I Omega, and rho E at its centre") {
    const double expectedPower = 0.5 * kBulbIntensity * floorSolidAngleFromBulb();
    for (const SolverMethod method : kLightMethods) {
        CAPTURE(methodName(method));
        const Solution s = solveLitScene("point_grey_floor.gltf", method);
        const std::size_t floor = s.scene.findSurface("Floor");
        REQUIRE(floor != Scene::npos);
        CHECK(s.power(floor) == relativeTo(expectedPower, 0.003));
        CHECK(s.totalPower() == relativeTo(expectedPower, 0.003));  // the black walls reflect nothing
        const ProbeReading reading = s.probe({0, 0, 0}, {0, 1, 0});
        CHECK(reading.radiosity.value().y == relativeTo(0.5 * pointSourceE(kBulbIntensity, kBulb, {0, 0, 0}, {0, 1, 0}), 1e-9));
    }
}

TEST_CASE("a closed grey room absorbs all of the bulb's power: every method, each other and the reference tracer agree") {
    // (1 - rho) sum A (H + F B) = 4 pi I and B = rho (H + F B), so sum A B = rho / (1 - rho) 4 pi I.
    const double expectedPower = 0.5 / (1 - 0.5) * 4 * std::numbers::pi * kBulbIntensity;
    std::vector<double> floorE;
    Scene scene;
    for (const SolverMethod method : kLightMethods) {
        CAPTURE(methodName(method));
        const Solution s = solveLitScene("point_grey_room.gltf", method);
        CHECK(s.totalPower() == relativeTo(expectedPower, 0.01));
        floorE.push_back(s.probe({-1, 0, 1}, {0, 1, 0}).irradiance.value().y);
        scene = s.scene;
    }
    for (std::size_t m = 1; m < floorE.size(); ++m) {
        CAPTURE(methodName(kLightMethods[m]));
        CHECK(floorE[m] == relativeTo(floorE[0], 0.02));
    }
    // The tracer shares nothing with the solvers but the scene, the ray caster and the lights' NEE.
    const RayCaster rays(scene);
    const PathTracer tracer(scene, rays);
    ReferenceRun run(tracer, locateReferencePoint(scene, {-1, 0, 1}, {0, 1, 0}));
    ReferenceStop stop;
    stop.relativeStandardError = 0.002;
    stop.samples = 1u << 20;
    const ReferenceEstimate reference = run.runUntil(stop);
    const double tolerance = 3 * reference.irradianceStandardError.y + 0.01 * reference.irradiance.value().y;
    for (std::size_t m = 0; m < floorE.size(); ++m) {
        CAPTURE(methodName(kLightMethods[m]));
        CHECK(std::abs(floorE[m] - reference.irradiance.value().y) <= tolerance);
    }
}

TEST_CASE("a spot lights its cone by glTF's smooth falloff and nothing beyond it") {
    const Solution s = solveLitScene("spot_floor.gltf", SolverMethod::GaussSeidel, 1.0);
    const double cosInner = std::cos(0.3), cosOuter = std::cos(0.5);
    for (const double angle : {0.0, 0.2, 0.35, 0.45, 0.6}) {
        CAPTURE(angle);
        const glm::dvec3 x(2 * std::tan(angle), 0, 0);
        const double c = std::cos(angle);
        const double t = std::clamp((c - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
        const double expected = 1.0 * c * c * c / 4 * t * t;  // I cos / r^2 with r = 2 / cos
        const ProbeReading reading = s.probe(x, {0, 1, 0});
        if (expected == 0)
            CHECK(reading.directIrradiance.value().x == 0.0);
        else
            CHECK(reading.directIrradiance.value().x == relativeTo(expected, 1e-9));
    }
}

TEST_CASE("a sun gives E cos(theta) wherever nothing shades it, and its shadow gets nothing") {
    const double normal = 1000.0 / 179.0, cos60 = 0.5;
    for (const SolverMethod method : {SolverMethod::GaussSeidel, SolverMethod::Hierarchical}) {
        CAPTURE(methodName(method));
        const Solution s = solveLitScene("sun_floor.gltf", method, 0.25);
        CHECK(s.probe({3, 0, 0}, {0, 1, 0}).directIrradiance.value().x == relativeTo(normal * cos60, 1e-9));
        CHECK(s.probe({0.5, 0, 0}, {0, 1, 0}).directIrradiance.value().x == relativeTo(normal * cos60, 1e-9));
        CHECK(s.probe({0, 1, 0}, {0, 1, 0}).directIrradiance.value().x == relativeTo(normal * cos60, 1e-9));  // the roof
        CHECK(s.probe({-1.5, 0, 0}, {0, 1, 0}).directIrradiance.value().x == 0.0);  // in the roof's shadow
        // The roof's shadow is its 2 m x 2 m square shifted along the sun: the floor's lit area is 96 m^2.
        CHECK(s.power(s.scene.findSurface("Floor")) == relativeTo(0.5 * normal * cos60 * 96, 0.005));
    }
}

TEST_CASE("radiant solve and probe accept a scene lit only by a point light, and --photometric gives lx and cd/m^2") {
    const Run solved = runRadiant("solve '" + lightFile("point_grey_floor.gltf") + "' --max-patch-area 0.25 --photometric --json -");
    REQUIRE(solved.status == 0);
    const auto report = nlohmann::json::parse(solved.out);
    CHECK(report["lights"] == 1);
    for (const auto& surface : report["surfaces"]) {
        const auto& power = surface["power_W"];
        const double flux = 179 * (0.265 * power[0].get<double>() + 0.670 * power[1].get<double>() + 0.065 * power[2].get<double>());
        CAPTURE(surface["name"].get<std::string>());
        if (surface["name"] == "Floor")
            CHECK(surface["luminous_flux_lm"].get<double>() == relativeTo(flux, 1e-9));
        else
            CHECK(surface["luminous_flux_lm"].get<double>() == 0.0);  // black: reflects nothing
    }

    const Run probed = runRadiant("probe '" + lightFile("point_grey_floor.gltf") + "' --point 0,0,0 --normal 0,1,0 --max-patch-area 0.25 --photometric --json -");
    REQUIRE(probed.status == 0);
    const auto reading = nlohmann::json::parse(probed.out);
    const double E = pointSourceE(kBulbIntensity, kBulb, {0, 0, 0}, {0, 1, 0});
    CHECK(reading["direct_irradiance_W_m2"][1].get<double>() == relativeTo(E, 1e-9));
    CHECK(reading["irradiance_W_m2"][1].get<double>() == relativeTo(E, 1e-9));
    // 179 cd at the floor's centre: I cos / r^2 in lx; B = rho E, L = B / pi in cd/m^2.
    CHECK(reading["illuminance_lx"].get<double>() == relativeTo(179 * E, 1e-9));
    CHECK(reading["luminance_cd_m2"].get<double>() == relativeTo(179 * 0.5 * E / std::numbers::pi, 1e-9));
    CHECK(!reading.contains("target"));  // nothing emits: no surface to measure by default

    // A coloured bulb of 100 cd gives 100 cos / r^2 lx, = 179 (0.265 E_r + 0.670 E_g + 0.065 E_b).
    const Run coloured = runRadiant("probe '" + lightFile("point_coloured_room.gltf") + "' --point 0,0,0 --normal 0,1,0 --max-patch-area 0.25 --photometric --json -");
    REQUIRE(coloured.status == 0);
    const auto c = nlohmann::json::parse(coloured.out);
    const auto& e = c["irradiance_W_m2"];
    CHECK(c["illuminance_lx"].get<double>() == relativeTo(100 * pointSourceE(1.0, kBulb, {0, 0, 0}, {0, 1, 0}), 1e-9));
    CHECK(c["illuminance_lx"].get<double>() ==
          relativeTo(179 * (0.265 * e[0].get<double>() + 0.670 * e[1].get<double>() + 0.065 * e[2].get<double>()), 1e-12));
    CHECK(e[1].get<double>() / e[0].get<double>() == relativeTo(0.5, 1e-9));
}

TEST_CASE("a scene with neither an emitting surface nor a light is refused in one line by the loader and every command") {
    try {
        (void)loadScene(lightFile("dark_room.gltf"));
        FAIL("a scene that nothing lights loaded");
    } catch (const RadiantError& error) {
        const std::string what = error.what();
        CHECK(contains(what, "dark_room.gltf"));
        CHECK(contains(what, "no surface emits and no light is supported: "));
        CHECK(!contains(what, "\n"));
    }
    for (const std::string command : {"solve", "probe", "reference"}) {
        CAPTURE(command);
        const std::string extra = command == "solve" ? "" : " --point 0,0,0 --normal 0,1,0";
        const Run run = runRadiant(command + " '" + lightFile("dark_room.gltf") + "'" + extra);
        CHECK(run.status == 2);
        CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
        CHECK(contains(run.err, "no surface emits and no light is supported: "));
    }
}

} // TEST_SUITE
