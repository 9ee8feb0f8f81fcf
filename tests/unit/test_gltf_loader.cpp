// The glTF loader on small hand-made files (tests/data/make_test_files.py writes them): geometry,
// transforms, index formats, buffers, materials, merging, and one test per kind of bad input that
// checks the one-line message names the file and the element.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/scene/GltfLoader.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {

std::string dataFile(const std::string& name) { return std::string(RADIANT_TEST_DATA_DIR) + "/gltf/" + name; }

/// The message of the RadiantError that loading `name` throws ("" when it loads).
std::string loadError(const std::string& name, const SceneLoadOptions& options = {}) {
    try {
        (void)loadGltf(dataFile(name), options);
    } catch (const RadiantError& e) {
        return e.what();
    }
    return "";
}

using radiant::test::contains;

bool anyWarningContains(const LoadedScene& loaded, const std::string& part) {
    return std::any_of(loaded.warnings.begin(), loaded.warnings.end(), [&](const std::string& w) { return contains(w, part); });
}

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("a square as two triangles loads as one quad face, whatever the container and index format") {
    for (const char* name : {"square.gltf", "square.glb", "square_u8.gltf", "square_u16.gltf", "square_nonindexed.gltf",
                             "square_external.gltf"}) {
        CAPTURE(name);
        const LoadedScene loaded = loadGltf(dataFile(name));
        CHECK(loaded.warnings.empty());
        REQUIRE(loaded.scene.surfaces.size() == 1);
        const Surface& surface = loaded.scene.surfaces[0];
        CHECK(surface.name == "square");
        CHECK(surface.origin == "mesh 0, primitive 0");
        REQUIRE(surface.faces.size() == 1);
        CHECK(surface.faces[0].vertices.size() == 4);
        CHECK(surface.area() == doctest::Approx(1.0).epsilon(1e-12).scale(0));
        CHECK(surface.faces[0].normal.y == doctest::Approx(1.0).scale(0));  // counter-clockwise winding kept
        REQUIRE(loaded.scene.materials.size() == 1);
        CHECK(loaded.scene.materials[0].reflectance.x == doctest::Approx(0.5).scale(0));
        CHECK(loaded.scene.name == dataFile(name));
    }
}

TEST_CASE("node transforms compose down the hierarchy (TRS and matrix)") {
    const LoadedScene loaded = loadGltf(dataFile("hierarchy.gltf"));
    REQUIRE(loaded.scene.surfaces.size() == 2);
    // Child: scale 2, rotate 90 degrees about x, then the parent's translation (0, 2, 0):
    // (x, 0, z) -> (2x, 2 - 2z, 0); area 4, normal +y -> +z.
    const Surface& child = loaded.scene.surfaces[0];
    CHECK(child.name == "child");
    CHECK(child.area() == doctest::Approx(4.0).epsilon(1e-6).scale(0));
    CHECK(child.faces[0].normal.z == doctest::Approx(1.0).epsilon(1e-6).scale(0));
    for (const glm::dvec3& v : child.faces[0].vertices) {
        CHECK(v.z == doctest::Approx(0.0).epsilon(1e-6));
        CHECK(v.y >= -1e-6);
        CHECK(v.y <= 2 + 1e-6);
    }
    const Surface& moved = loaded.scene.surfaces[1];
    CHECK(moved.name == "moved");
    CHECK(moved.area() == doctest::Approx(1.0).epsilon(1e-6).scale(0));
    for (const glm::dvec3& v : moved.faces[0].vertices) CHECK(v.x >= 5 - 1e-6);
}

TEST_CASE("surfaces are named after node, else mesh, with a suffix where a name repeats") {
    const LoadedScene loaded = loadGltf(dataFile("names.gltf"));
    REQUIRE(loaded.scene.surfaces.size() == 4);
    CHECK(loaded.scene.surfaces[0].name == "wall");
    CHECK(loaded.scene.surfaces[1].name == "wall (2)");
    CHECK(loaded.scene.surfaces[2].name == "square mesh");
    CHECK(loaded.scene.surfaces[3].name == "mesh 1");
    CHECK(loaded.scene.surfaces[3].origin == "mesh 1, primitive 0");
    CHECK(loaded.scene.materials.size() == 1);  // one glTF material used four times is one material
}

TEST_CASE("coplanar triangles pair into quads, one face per square") {
    SceneLoadOptions ungrouped;
    ungrouped.groupCoplanarTriangles = false;
    const LoadedScene loaded = loadGltf(dataFile("two_squares.gltf"), ungrouped);
    REQUIRE(loaded.scene.surfaces.size() == 1);
    const auto& faces = loaded.scene.surfaces[0].faces;
    REQUIRE(faces.size() == 2);
    for (const Face& f : faces) {
        CHECK(f.vertices.size() == 4);
        CHECK(f.area == doctest::Approx(1.0).scale(0));
    }
    // Grouped (the default), the two squares side by side are one flat region: one 2 m^2 rectangle.
    const LoadedScene grouped = loadGltf(dataFile("two_squares.gltf"));
    REQUIRE(grouped.scene.surfaces[0].faces.size() == 1);
    CHECK(grouped.scene.surfaces[0].faces[0].vertices.size() == 4);
    CHECK(grouped.scene.surfaces[0].faces[0].area == doctest::Approx(2.0).scale(0));
}

TEST_CASE("materials: emissive strength, extras.radiant override, texture mean") {
    {
        const LoadedScene loaded = loadGltf(dataFile("emissive_strength.gltf"));
        const Material& m = loaded.scene.materials.at(0);
        CHECK(m.name == "lamp");
        CHECK(m.exitance.value().x == doctest::Approx(8.0).scale(0));   // 1 x 8 W/m^2
        CHECK(m.exitance.value().y == doctest::Approx(4.0).scale(0));   // 0.5 x 8
        CHECK(m.exitance.value().z == doctest::Approx(2.0).scale(0));   // 0.25 x 8
        CHECK(m.reflectance.z == doctest::Approx(0.6).scale(0));
    }
    {
        const LoadedScene loaded = loadGltf(dataFile("extras_override.gltf"));
        const Material& m = loaded.scene.materials.at(0);
        CHECK(m.reflectance.x == doctest::Approx(0.25).scale(0));
        CHECK(m.reflectance.z == doctest::Approx(0.75).scale(0));
        CHECK(m.exitance.value().y == doctest::Approx(200.0).scale(0));
    }
    {
        // A white and a black texel: the linear mean is one half, times the factor.
        const LoadedScene loaded = loadGltf(dataFile("textured.gltf"));
        CHECK(loaded.warnings.empty());
        const Material& m = loaded.scene.materials.at(0);
        CHECK(m.reflectance.x == doctest::Approx(0.8 * 0.5).scale(0));
        CHECK(m.reflectance.y == doctest::Approx(0.6 * 0.5).scale(0));
        CHECK(m.reflectance.z == doctest::Approx(0.4 * 0.5).scale(0));
    }
}

TEST_CASE("bad input: missing, truncated or malformed files") {
    const std::string missing = loadError("no_such_scene.gltf");
    CHECK(contains(missing, "no_such_scene.gltf: no such file"));
    for (const char* name : {"truncated.gltf", "malformed.gltf", "truncated.glb"}) {
        CAPTURE(name);
        const std::string error = loadError(name);
        CHECK(contains(error, dataFile(name) + ": "));
        CHECK(error.find('\n') == std::string::npos);
    }
}

TEST_CASE("bad input: a JSON error inside a kilobyte of base64 is one short line naming the file and the place") {
    // The file breaks its 1 kB data URI with a line break; the parser's message quoted all of it.
    const std::string name = "malformed_base64.gltf";
    const std::string error = loadError(name);
    INFO(error);
    CHECK(error.rfind(dataFile(name) + ": ", 0) == 0);
    CHECK(error.find('\n') == std::string::npos);
    const std::string message = error.substr(dataFile(name).size() + 2);
    CHECK(message.size() <= 160);
    // The line break ends line 2, so the parser stops at the start of line 3.
    CHECK(contains(message, "malformed JSON at line 3, column 0"));
    // Not the payload: no run of base64 longer than the few characters kept to show where it stopped.
    std::size_t longestRun = 0, run = 0;
    for (const char c : message) {
        run = (std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/') ? run + 1 : 0;
        longestRun = std::max(longestRun, run);
    }
    CHECK(longestRun <= 16);
}

TEST_CASE("bad input: missing or short buffers, accessors out of range") {
    const std::string missing = loadError("missing_buffer.gltf");
    CHECK(contains(missing, "missing_buffer.gltf: "));
    CHECK(contains(missing, "does_not_exist.bin"));
    CHECK(missing.find('\n') == std::string::npos);

    const std::string shortBuffer = loadError("short_buffer.gltf");
    CHECK(contains(shortBuffer, "short_buffer.gltf: "));
    CHECK(shortBuffer.find('\n') == std::string::npos);
    CHECK((contains(shortBuffer, "4096") || contains(shortBuffer, "buffer")));

    CHECK(contains(loadError("accessor_overrun.gltf"),
                   "accessor_overrun.gltf: mesh 0, primitive 0, POSITION accessor 0: 40 elements need 480 bytes but buffer view 0 has 48"));
    const std::string missingAccessor = loadError("accessor_missing.gltf");
    CHECK(contains(missingAccessor, "accessor_missing.gltf: "));
    CHECK(contains(missingAccessor, "9"));
}

TEST_CASE("bad input: index out of range, non-finite positions") {
    CHECK(contains(loadError("index_out_of_range.gltf"),
                   "index_out_of_range.gltf: mesh 0, primitive 0: index 7 out of range (vertex count 4)"));
    const std::string nan = loadError("nan_position.gltf");
    CHECK(contains(nan, "nan_position.gltf: mesh 0, primitive 0: vertex 1 has a position that is not finite"));
    CHECK(contains(loadError("infinite_position.gltf"), "infinite_position.gltf: mesh 0, primitive 0: vertex 1"));
}

TEST_CASE("recoverable input: zero-area triangles and lines are dropped with one warning each") {
    const LoadedScene zero = loadGltf(dataFile("zero_area.gltf"));
    REQUIRE(zero.warnings.size() == 1);
    CHECK(contains(zero.warnings[0], "zero_area.gltf: dropped 2 zero-area triangle(s), the first in mesh 0, primitive 0 (triangle 2)"));
    CHECK(zero.scene.totalArea() == doctest::Approx(1.0).scale(0));

    const LoadedScene lines = loadGltf(dataFile("lines.gltf"));
    CHECK(lines.scene.surfaces.size() == 1);
    CHECK(anyWarningContains(lines, "lines.gltf: mesh 0, primitive 1: mode 1 is not a triangle list (mode 4); skipped"));
}

TEST_CASE("materials out of range: reflectance >= 1 is clamped with a warning, negative emission refused") {
    const LoadedScene bright = loadGltf(dataFile("reflectance_one.gltf"));
    REQUIRE(bright.warnings.size() == 1);
    CHECK(contains(bright.warnings[0], "reflectance_one.gltf: material 0 'too white': reflectance (1, 1.2, 0.5)"));
    CHECK(contains(bright.warnings[0], "clamped to 0.999"));
    const Rgb rho = bright.scene.materials.at(0).reflectance;
    CHECK(rho.x == doctest::Approx(0.999).scale(0));
    CHECK(rho.y == doctest::Approx(0.999).scale(0));
    CHECK(rho.z == doctest::Approx(0.5).scale(0));

    CHECK(contains(loadError("negative_emission.gltf"),
                   "negative_emission.gltf: material 0 'dark lamp': negative or non-finite emission (-1, 0, 0) W/m^2"));
}

TEST_CASE("a triangle budget refuses large files with the numbers") {
    SceneLoadOptions options;
    options.triangleBudget = 1;
    try {
        (void)loadGltf(dataFile("square.gltf"), options);
        FAIL("expected BudgetError");
    } catch (const BudgetError& e) {
        CHECK(contains(e.what(), "square.gltf: the scene has 2 triangles; the budget is 1"));
    }
    options.triangleBudget = 2;
    CHECK_NOTHROW((void)loadGltf(dataFile("square.gltf"), options));
}

} // TEST_SUITE
