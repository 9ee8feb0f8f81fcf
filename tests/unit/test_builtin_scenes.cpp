// Built-in scenes: made in code, shipped as assets/*.gltf (tools/make_assets), loaded by name.
// Areas against their closed forms, materials as documented, and code -> glTF -> Scene round trips.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <unistd.h>
#include <sstream>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/scene/GltfWriter.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;

namespace {

std::filesystem::path scratchDirectory() {
    const auto dir = std::filesystem::temp_directory_path() / ("radiant-scenes-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Faces equal up to float rounding of the positions and a cyclic shift of the corners.
bool sameFace(const Face& a, const Face& b, double tolerance) {
    const std::size_t n = a.vertices.size();
    if (b.vertices.size() != n) return false;
    for (std::size_t shift = 0; shift < n; ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < n && all; ++i) all = glm::distance(a.vertices[i], b.vertices[(i + shift) % n]) <= tolerance;
        if (all) return true;
    }
    return false;
}

const Material& materialOf(const Scene& scene, const std::string& surface) {
    return scene.materials.at(scene.surfaces.at(scene.findSurface(surface)).material);
}

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("the built-in names") {
    const auto names = builtinSceneNames();
    REQUIRE(names.size() == 5);
    CHECK(names.front() == "cornell-box");
    for (const auto& name : names) CHECK(makeBuiltinScene(name).name == name);
    CHECK_THROWS_AS((void)makeBuiltinScene("teapot"), RadiantError);
    CHECK_FALSE(assetDirectory().empty());
}

TEST_CASE("every built-in loads from its asset without a warning, with its surfaces and areas") {
    const std::map<std::string, std::size_t> surfaceCounts{
        {"cornell-box", 8}, {"unit-cube", 6}, {"furnace", 6}, {"parallel-plates", 2}, {"perpendicular-plates", 2}};
    // Closed forms: a unit cube has 6 m^2; the 2 x 1 x 1.5 furnace 2 (2 x 1.5 + 2 x 1 + 1 x 1.5) = 13 m^2.
    const std::map<std::string, double> totalAreas{
        {"unit-cube", 6.0}, {"furnace", 13.0}, {"parallel-plates", 2.0}, {"perpendicular-plates", 2.0}};
    for (const auto& name : builtinSceneNames()) {
        CAPTURE(name);
        const LoadedScene loaded = loadScene(name);
        CHECK(loaded.warnings.empty());
        CHECK(loaded.scene.name == name);
        CHECK(loaded.scene.surfaces.size() == surfaceCounts.at(name));
        if (totalAreas.count(name)) CHECK(loaded.scene.totalArea() == doctest::Approx(totalAreas.at(name)).epsilon(1e-6).scale(0));
    }
    const Scene cornell = loadScene("cornell-box").scene;
    // Published corners (mm): the floor is a trapezoid, the back wall too; the light 130 x 105 mm.
    CHECK(cornell.surfaces[cornell.findSurface("floor")].area() == doctest::Approx((0.5528 + 0.5496) / 2 * 0.5592).epsilon(1e-6).scale(0));
    CHECK(cornell.surfaces[cornell.findSurface("light")].area() == doctest::Approx(0.130 * 0.105).epsilon(1e-6).scale(0));
    CHECK(cornell.surfaces[cornell.findSurface("ceiling")].area() ==
          doctest::Approx(0.556 * 0.5592 - 0.130 * 0.105).epsilon(1e-6).scale(0));
    CHECK(cornell.surfaces[cornell.findSurface("back wall")].area() == doctest::Approx((0.5496 + 0.556) / 2 * 0.5488).epsilon(1e-6).scale(0));
    // The warped left wall stays two triangles; every other flat quad comes back as quads.
    CHECK(cornell.surfaces[cornell.findSurface("left wall")].faces.size() == 2);
    CHECK(cornell.surfaces[cornell.findSurface("ceiling")].faces.size() == 8);
    CHECK(cornell.surfaces[cornell.findSurface("tall block")].faces.size() == 5);
}

TEST_CASE("built-in materials carry the documented SI values") {
    const Scene cube = loadScene("unit-cube").scene;
    CHECK(materialOf(cube, "ceiling").exitance.value() == Rgb(1.0));
    CHECK(materialOf(cube, "ceiling").reflectance == Rgb(0.5));
    CHECK(materialOf(cube, "floor").reflectance == Rgb(0.5));
    CHECK_FALSE(materialOf(cube, "floor").emits());

    const Scene furnace = loadScene("furnace").scene;
    CHECK(furnace.materials.size() == 1);
    CHECK(furnace.materials[0].reflectance == Rgb(0.5));
    CHECK(furnace.materials[0].exitance.value() == Rgb(1.0));

    for (const char* name : {"parallel-plates", "perpendicular-plates"}) {
        const Scene plates = loadScene(name).scene;
        CHECK(materialOf(plates, "emitter").exitance.value() == Rgb(1.0));
        CHECK(materialOf(plates, "emitter").reflectance == Rgb(0.0));
        CHECK(materialOf(plates, "receiver").reflectance == Rgb(0.5));
    }
    const Scene cornell = loadScene("cornell-box").scene;
    CHECK(materialOf(cornell, "light").exitance.value() == Rgb(17, 12, 4));
    CHECK(materialOf(cornell, "left wall").reflectance == Rgb(0.63, 0.065, 0.05));
    CHECK(materialOf(cornell, "right wall").reflectance == Rgb(0.14, 0.45, 0.09));
}

TEST_CASE("closed built-in boxes face inward and plates face each other") {
    for (const char* name : {"unit-cube", "furnace"}) {
        const Scene box = loadScene(name).scene;
        glm::dvec3 centre(0.0);
        std::size_t corners = 0;
        for (const Surface& s : box.surfaces)
            for (const Face& f : s.faces)
                for (const glm::dvec3& v : f.vertices) centre += v, ++corners;
        centre /= static_cast<double>(corners);
        for (const Surface& s : box.surfaces)
            for (const Face& f : s.faces) CHECK(glm::dot(f.normal, centre - f.vertices[0]) > 0);
    }
    const Scene plates = loadScene("parallel-plates").scene;
    const Face& emitter = plates.surfaces[plates.findSurface("emitter")].faces[0];
    const Face& receiver = plates.surfaces[plates.findSurface("receiver")].faces[0];
    CHECK(emitter.normal.y == doctest::Approx(1.0).scale(0));
    CHECK(receiver.normal.y == doctest::Approx(-1.0).scale(0));
    CHECK(receiver.vertices[0].y - emitter.vertices[0].y == doctest::Approx(1.0).scale(0));
}

TEST_CASE("round trip: code -> glTF (.gltf and .glb) -> Scene gives the same scene") {
    const auto dir = scratchDirectory();
    for (const auto& name : builtinSceneNames()) {
        const Scene made = makeBuiltinScene(name);
        for (const char* extension : {".gltf", ".glb"}) {
            CAPTURE(name);
            CAPTURE(extension);
            const std::string path = (dir / (name + extension)).string();
            writeGltf(made, path);
            const LoadedScene loaded = loadGltf(path);
            CHECK(loaded.warnings.empty());
            REQUIRE(loaded.scene.surfaces.size() == made.surfaces.size());
            for (std::size_t s = 0; s < made.surfaces.size(); ++s) {
                const Surface& a = made.surfaces[s];
                const Surface& b = loaded.scene.surfaces[s];
                CHECK(a.name == b.name);
                CHECK(b.area() == doctest::Approx(a.area()).epsilon(1e-6).scale(0));
                const Material& ma = made.materials[a.material];
                const Material& mb = loaded.scene.materials[b.material];
                CHECK(ma.name == mb.name);
                CHECK(ma.reflectance == mb.reflectance);           // exact: extras.radiant
                CHECK(ma.exitance.value() == mb.exitance.value());
                REQUIRE(a.faces.size() == b.faces.size());
                for (std::size_t f = 0; f < a.faces.size(); ++f) {
                    CHECK(sameFace(a.faces[f], b.faces[f], 1e-6));  // float positions in the file
                    CHECK(glm::dot(a.faces[f].normal, b.faces[f].normal) == doctest::Approx(1.0).scale(0));
                }
            }
        }
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("the committed assets are what tools/make_assets writes today") {
    const auto dir = scratchDirectory();
    for (const auto& name : builtinSceneNames()) {
        CAPTURE(name);
        const auto fresh = dir / (name + ".gltf");
        writeGltf(makeBuiltinScene(name), fresh.string());
        CHECK(readAll(fresh) == readAll(std::filesystem::path(assetDirectory()) / (name + ".gltf")));
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("loadScene treats anything else as a path") {
    try {
        (void)loadScene("no-such-scene");
        FAIL("expected RadiantError");
    } catch (const RadiantError& e) {
        CHECK(std::string(e.what()) == "no-such-scene: no such file");
    }
    const LoadedScene byPath = loadScene(assetDirectory() + "/unit-cube.gltf");
    CHECK(byPath.scene.surfaces.size() == 6);
}

TEST_CASE("the loaded Cornell box meshes like the one built in code") {
    const Scene loaded = loadScene("cornell-box").scene;
    const Scene made = makeCornellBox();
    for (const double maxArea : {1e-2, 1e-4}) {
        const PatchMesh a = meshScene(loaded, {maxArea});
        const PatchMesh b = meshScene(made, {maxArea});
        CHECK(a.totalArea() == doctest::Approx(loaded.totalArea()).epsilon(1e-9).scale(0));
        CHECK(a.totalArea() == doctest::Approx(b.totalArea()).epsilon(1e-6).scale(0));
        CHECK(a.size() == b.size());
    }
}

} // TEST_SUITE
