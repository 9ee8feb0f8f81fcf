// Scenes as Blender's glTF exporter writes them (tests/data/make_blender_scenes.py): double-sided
// materials against the parallel-plates closed form and a closed room's energy balance (docs/reference.md),
// punctual lamps read as lights, a missing texture, a camera, and names of multi-material
// objects. The command line is run for what only it does (warnings on stderr and in the JSON).
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/Solver.h"
#include "tests/support/RunRadiant.h"
#include "tests/support/Common.h"
#include "tests/support/CatalogViewFactors.h"

using namespace radiant;
namespace fs = std::filesystem;

namespace {

std::string blenderFile(const std::string& name) { return std::string(RADIANT_TEST_DATA_DIR) + "/blender/" + name; }

using radiant::test::contains;

using radiant::test::anyContains;

/// Directly opposed parallel rectangles a x b at distance c (docs/reference.md, Howell).
using radiant::test::parallelRectangles;

struct Solved {
    Scene scene;
    PatchMesh mesh;
    std::vector<Rgb> B;

    /// Area-weighted mean radiosity (red band) and area of one surface.
    [[nodiscard]] double meanB(const std::string& surface) const {
        const std::size_t s = scene.findSurface(surface);
        REQUIRE(s != Scene::npos);
        double area = 0, power = 0;
        for (std::size_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
            area += mesh.patches[i].area;
            power += mesh.patches[i].area * B[i].x;
        }
        return power / area;
    }
    [[nodiscard]] double power(const std::string& surface) const { return meanB(surface) * scene.surfaces[scene.findSurface(surface)].area(); }
};

Solved solveBlenderScene(const std::string& file, double maxPatchArea) {
    Solved solved{loadScene(blenderFile(file)).scene, {}, {}};
    solved.mesh = meshScene(solved.scene, MeshingOptions{maxPatchArea});
    const auto solver = makeSolver(SolverMethod::GaussSeidel, solved.scene, solved.mesh);
    for (int k = 0; k < 10000 && solver->lastStats().residual > 1e-7; ++k) solver->step();
    REQUIRE(solver->lastStats().residual <= 1e-7);
    solved.B = solver->solution();
    return solved;
}

using Run = test::CommandRun;
using test::runRadiant;

std::size_t lineCount(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("Blender's default plane facing up, double-sided, lights the floor below as parallel plates do") {
    // Lamp: 2 m x 2 m, black, 10 W/m^2 from each side, 1 m above a 2 m x 2 m floor of reflectance 0.5.
    // Nothing else is in the scene, so the floor's top sees only the lamp's underside, once:
    // B = rho M F(2, 2, 1), F from the closed form, not from the code's quadrature.
    const Solved solved = solveBlenderScene("plane_lamp.gltf", 0.04);
    REQUIRE(solved.scene.surfaces.size() == 4);
    CHECK(solved.scene.doubleSidedSurfaceCount() == 2);
    CHECK(solved.scene.surfaces[0].name == "Lamp");
    CHECK(solved.scene.surfaces[1].name == "Lamp (back)");
    CHECK(solved.scene.surfaces[1].faces[0].normal.y == doctest::Approx(-1.0).scale(0));
    const double expected = 0.5 * 10 * parallelRectangles(2, 2, 1);
    CHECK(solved.meanB("Floor") == doctest::Approx(expected).epsilon(0.01).scale(0));
    CHECK(solved.meanB("Lamp (back)") == doctest::Approx(10.0).epsilon(1e-9).scale(0));  // emits down, reflects nothing
    CHECK(solved.meanB("Lamp") == doctest::Approx(10.0).epsilon(1e-9).scale(0));         // and up, into nothing
    CHECK(solved.meanB("Floor (back)") == 0.0);  // faces the void below

    // The probe answers with the side whose front faces it: at the floor's centre looking up, the
    // lit top; from above the lamp looking down, its top (not the underside that shares the plane).
    const RayCaster rays(solved.scene);
    const Probe probe(solved.scene, solved.mesh, &rays);
    CHECK(solved.scene.surfaces[probe.locate({0, 0, 0}, {0, 1, 0}).surface].name == "Floor");
    CHECK(solved.scene.surfaces[probe.locate({0, 0, 0}, {0, -1, 0}).surface].name == "Floor (back)");
    CHECK(solved.scene.surfaces[probe.locate({0, 1, 0}, {0, -1, 0}).surface].name == "Lamp (back)");
    // A ray leaving the floor's top meets the lamp's underside; one from above meets its top.
    const auto up = rays.intersect({0.1, 0, 0.1}, {0, 1, 0});
    REQUIRE(up);
    CHECK(solved.scene.surfaces[up->surface].name == "Lamp (back)");
    CHECK(up->distance == doctest::Approx(1.0).scale(0));
    const auto down = rays.intersect({0.1, 2, 0.1}, {0, -1, 0});
    REQUIRE(down);
    CHECK(solved.scene.surfaces[down->surface].name == "Lamp");
    // Leaving the lamp's underside from its plane, the ray is not stopped by the twin at distance 0.
    const auto fromLamp = rays.intersect({0.1, 1, 0.1}, {0, -1, 0});
    REQUIRE(fromLamp);
    CHECK(solved.scene.surfaces[fromLamp->surface].name == "Floor");
    CHECK(!rays.occluded({0.1, 1, 0.1}, {0.2, 0, 0.3}));
}

TEST_CASE("a room made of Blender's cube (normals outward), double-sided, is lit inside and balances") {
    // Closed enclosure of uniform reflectance 0.5 (docs/reference.md): (1 - rho) sum A B = sum A E over the
    // inside; the lamp (0.5 m x 0.5 m, 10 W/m^2 from each side) emits 5 W.
    const Solved solved = solveBlenderScene("cube_room.gltf", 0.1);
    CHECK(solved.scene.doubleSidedSurfaceCount() == 2);
    const double inside = solved.power("Cube (back)") + solved.power("Lamp") + solved.power("Lamp (back)");
    CHECK(0.5 * inside == doctest::Approx(5.0).epsilon(0.02).scale(0));
    // Every inside wall is lit, the outside is not.
    const std::size_t back = solved.scene.findSurface("Cube (back)");
    for (std::size_t i = solved.mesh.surfaceFirstPatch[back]; i < solved.mesh.surfaceFirstPatch[back + 1]; ++i)
        CHECK(solved.B[i].x > 0.1);
    CHECK(solved.meanB("Cube") == 0.0);
}

TEST_CASE("a Blender point lamp is read as a light, and a scene lit only by it is solved") {
    // The lamp-only scene used to be refused; the closed forms are in test_punctual_lights.cpp.
    const LoadedScene loaded = loadScene(blenderFile("point_lamp_only.gltf"));
    REQUIRE(loaded.scene.lights.size() == 1);
    CHECK(loaded.scene.lights[0].name == "Lamp");
    CHECK(loaded.ignoredLights == 0);
    CHECK(!anyContains(loaded.scene.warnings, "Lamp"));
    const Run run = runRadiant("probe '" + blenderFile("point_lamp_only.gltf") + "' --point 0,0,0 --normal 0,1,0 --max-patch-area 0.05");
    CHECK(run.status == 0);
    // 683 / (4 pi) cd at 179 lm/W, 2 m up: E = I / d^2 at the floor's centre.
    const auto reading = nlohmann::json::parse(run.out);
    CHECK(reading["irradiance_W_m2"][0].get<double>() == doctest::Approx(683 / (4 * std::numbers::pi) / 179 / 4).epsilon(1e-6).scale(0));
}

TEST_CASE("a missing texture is a warning naming the file and the grey used, wherever the command runs") {
    // A same-named file in the current directory must not stand in for it (it is not a PNG: were it
    // read, the load would fail).
    const fs::path here = fs::current_path();
    const fs::path elsewhere = fs::temp_directory_path() / ("radiant-cwd-" + std::to_string(::getpid()));
    fs::create_directories(elsewhere);
    std::ofstream(elsewhere / "floor.png") << "not a png";
    fs::current_path(elsewhere);
    LoadedScene loaded;
    CHECK_NOTHROW(loaded = loadScene(blenderFile("missing_texture.gltf")));
    fs::current_path(here);
    fs::remove_all(elsewhere);

    const std::size_t floor = loaded.scene.findSurface("Floor");
    REQUIRE(floor != Scene::npos);
    const Rgb rho = loaded.scene.materials[loaded.scene.surfaces[floor].material].reflectance;
    CHECK(rho.x == doctest::Approx(0.5).scale(0));  // a mid grey, not the white factor clamped to 0.999
    INFO(loaded.scene.warnings.size());
    CHECK(anyContains(loaded.scene.warnings, "image 0 'floor.png': not found in"));
    CHECK(anyContains(loaded.scene.warnings, "'floor.png' could not be read; using reflectance (0.5, 0.5, 0.5)"));
    CHECK(loaded.warnings == loaded.scene.warnings);

    // solve: every warning on stderr and in the JSON; probe likewise.
    const Run solved = runRadiant("solve '" + blenderFile("missing_texture.gltf") + "' --max-patch-area 0.25 --json -");
    REQUIRE(solved.status == 0);
    const nlohmann::json report = nlohmann::json::parse(solved.out);
    CHECK(report["warnings"].size() == loaded.scene.warnings.size());
    CHECK(contains(report["warnings"].dump(), "floor.png"));
    CHECK(contains(solved.err, "radiant: warning: "));
    CHECK(contains(solved.err, "floor.png"));
    const Run probed = runRadiant("probe '" + blenderFile("missing_texture.gltf") + "' --point 0,0,0 --normal 0,1,0 --max-patch-area 0.25");
    REQUIRE(probed.status == 0);
    CHECK(contains(nlohmann::json::parse(probed.out)["warnings"].dump(), "floor.png"));
    CHECK(contains(probed.err, "floor.png"));
    // A scene without warnings has an empty list, not a missing field.
    const Run clean = runRadiant("solve parallel-plates --max-patch-area 0.25 --json -");
    REQUIRE(clean.status == 0);
    CHECK(nlohmann::json::parse(clean.out)["warnings"] == nlohmann::json::array());
}

TEST_CASE("a glTF camera is read with its node's pose, and a multi-material object names its parts") {
    const LoadedScene loaded = loadScene(blenderFile("room_camera.gltf"));
    REQUIRE(loaded.scene.cameras.size() == 1);
    const SceneCamera& camera = loaded.scene.cameras[0];
    CHECK(camera.name == "Camera");
    CHECK(glm::length(camera.position - glm::dvec3(3, 1, 0)) < 1e-9);
    CHECK(glm::length(camera.forward - glm::dvec3(-1, 0, 0)) < 1e-9);  // -z turned 90 degrees about +y
    CHECK(glm::length(camera.up - glm::dvec3(0, 1, 0)) < 1e-9);
    CHECK(camera.verticalFieldOfView == doctest::Approx(0.6911112070083618).scale(0));
    CHECK(camera.aspectRatio == doctest::Approx(16.0 / 9.0).scale(0));
    // One object of two materials: "Room/Floor", "Room/Wall", not "Room" and "Room (2)".
    CHECK(loaded.scene.findSurface("Room/Floor") != Scene::npos);
    CHECK(loaded.scene.findSurface("Room/Wall") != Scene::npos);
    CHECK(loaded.scene.findSurface("Lamp") != Scene::npos);
    CHECK(loaded.scene.doubleSidedSurfaceCount() == 0);  // single-sided materials stay one surface each
    CHECK(loaded.scene.surfaces.size() == 3);
}

TEST_CASE("a form-factor matrix over budget is refused naming the scene's file") {
    const Run run = runRadiant("solve '" + blenderFile("cube_room.gltf") + "' --method jacobi --max-patch-area 0.0002");
    INFO(run.err);
    CHECK(run.status == 2);
    CHECK(lineCount(run.err) == 1);
    CHECK(contains(run.err, "cube_room.gltf: form-factor matrix: a form-factor matrix for"));
}

TEST_CASE("an external buffer outside the scene's folder is allowed") {
    const LoadedScene loaded = loadScene(blenderFile("outside_folder.gltf"));
    CHECK(loaded.scene.totalArea() == doctest::Approx(1.0).scale(0));
}

} // TEST_SUITE
