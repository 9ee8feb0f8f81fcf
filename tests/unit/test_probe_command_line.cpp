// ctest-labels: threads
// A point copied from the lab reaches `radiant probe` intact: the snap of a point a little off a
// surface (against the closed-form nearest point), and the lab's "Copy as command" line parsed and
// run in-process (app/cli), probing the very point the lab picked.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/cli/CommandLine.h"
#include "app/cli/ProbeCommandLine.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;

namespace {

/// The unit square in z = 0, facing +z.
Scene unitPlate() {
    Scene scene;
    scene.name = "plate";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb(Rgb(1.0))});
    Face face;
    face.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    face.updateGeometry();
    scene.surfaces.push_back({"plate", 0, {face}, "test"});
    return scene;
}

/// Splits a POSIX shell line into words, honouring single quotes (all probeCommandLine writes).
std::vector<std::string> shellWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false, quoted = false, escaped = false;
    for (const char c : line) {
        if (escaped) {
            word += c;
            escaped = false;
        } else if (quoted) {
            if (c == '\'') quoted = false; else word += c;
        } else if (c == '\'') {
            quoted = inWord = true;
        } else if (c == '\\') {
            escaped = inWord = true;
        } else if (c == ' ') {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) words.push_back(word);
    return words;
}

/// Runs `radiant <words...> --json=FILE` in this process and returns the JSON it wrote.
nlohmann::json runInProcess(std::vector<std::string> words) {
    const std::string output = "/tmp/radiant-test-probe-line-" + std::to_string(::getpid()) + ".json";
    words.push_back("--json=" + output);
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    const app::ParsedCommandLine parsed = app::parseCommandLine(static_cast<int>(argv.size()), argv.data());
    REQUIRE(parsed.action);
    REQUIRE(parsed.action() == 0);
    std::ifstream in(output);
    nlohmann::json json = nlohmann::json::parse(in);
    std::remove(output.c_str());
    return json;
}

glm::dvec3 jsonVector(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

} // namespace

TEST_SUITE("probe command line") {

TEST_CASE("probe snap: a point within 1 mm of a face moves to its nearest point, on it or farther, it does not") {
    const Scene scene = unitPlate();
    const PatchMesh mesh = meshScene(scene, {1.0});
    const Probe probe(scene, mesh, nullptr);

    // Above the inside: straight down, 0.445 mm.
    std::optional<SurfaceSnap> snap = probe.snapOntoSurface({0.3, 0.6, 0.000445}, 1e-3);
    REQUIRE(snap);
    CHECK(glm::length(snap->point - glm::dvec3(0.3, 0.6, 0.0)) < 1e-15);
    CHECK(snap->distance == doctest::Approx(0.000445).scale(0).epsilon(1e-12));
    CHECK(snap->surface == 0);
    CHECK_NOTHROW((void)probe.locate(snap->point, {0, 0, 1}));

    // Beside an edge, above the plane: the nearest point is on the edge, sqrt(0.3^2 + 0.4^2) = 0.5 mm away.
    snap = probe.snapOntoSurface({1.0003, 0.5, 0.0004}, 1e-3);
    REQUIRE(snap);
    CHECK(glm::length(snap->point - glm::dvec3(1.0, 0.5, 0.0)) < 1e-15);
    CHECK(snap->distance == doctest::Approx(0.0005).scale(0).epsilon(1e-12));

    // 2 mm away: refused, as before.
    CHECK_FALSE(probe.snapOntoSurface({0.3, 0.6, 0.002}, 1e-3).has_value());
    CHECK_THROWS_AS((void)probe.locate({0.3, 0.6, 0.002}, {0, 0, 1}), RadiantError);
    // Already on the surface (within locate's tolerance): left alone.
    CHECK_FALSE(probe.snapOntoSurface({0.3, 0.6, 0.0}, 1e-3).has_value());
}

TEST_CASE("probe command: a point typed 0.445 mm off the left wall is probed on it, with a warning in the JSON") {
    const Scene scene = loadScene("cornell-box").scene;
    const std::size_t wall = scene.findSurface("left wall");
    REQUIRE(wall != Scene::npos);
    const Face& face = scene.surfaces[wall].faces.front();
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : face.vertices) centre += v / static_cast<double>(face.vertices.size());
    const glm::dvec3 typed = centre + 0.000445 * face.normal;  // in front of the wall, in the room

    const nlohmann::json out = runInProcess({"radiant", "probe", "cornell-box", "--point=" + app::roundTripVector(typed),
                                             "--normal=" + app::roundTripVector(face.normal), "--method=jacobi",
                                             "--max-patch-area=0.05", "--tolerance=1e-3"});
    CHECK(out["surface"] == "left wall");
    CHECK(glm::length(jsonVector(out["point"]) - centre) < 1e-12);
    bool warned = false;
    for (const auto& w : out["warnings"]) warned = warned || w.get<std::string>().find("moved onto it") != std::string::npos;
    CHECK(warned);
}

TEST_CASE("the lab's copied probe command parses and probes the very point the lab picked") {
    const Scene scene = loadScene("cornell-box").scene;
    const RayCaster rays(scene);
    // As the lab picks: a ray from the camera's side of the open front into the box, onto the floor.
    const glm::dvec3 origin{0.278, 0.273, -0.8};
    const glm::dvec3 direction = glm::normalize(glm::dvec3{0.41, 0.0, 0.11} - origin);
    const std::optional<RayHit> hit = rays.intersect(origin, direction);
    REQUIRE(hit);
    const glm::dvec3 normal = glm::dot(hit->normal, direction) > 0 ? -hit->normal : hit->normal;

    app::ProbeCommandInputs inputs;
    inputs.scene = "cornell-box";
    inputs.point = hit->point;
    inputs.normal = normal;
    inputs.target = "light";
    inputs.method = SolverMethod::Jacobi;
    inputs.maxPatchArea = 0.05;
    inputs.tolerance = 1e-3;
    const std::string line = app::probeCommandLine(inputs);
    CAPTURE(line);
    const std::vector<std::string> words = shellWords(line);
    REQUIRE(words.size() >= 3);
    CHECK(words[0] == "radiant");
    CHECK(words[1] == "probe");

    const nlohmann::json out = runInProcess(words);
    CHECK(out["surface"] == scene.surfaces[hit->surface].name);
    CHECK(out["method"] == "jacobi");
    CHECK(out["target"]["name"] == "light");
    CHECK(glm::length(jsonVector(out["point"]) - hit->point) < 1e-12);
    CHECK(glm::length(jsonVector(out["normal"]) - normal) < 1e-12);
    for (const auto& w : out["warnings"]) CHECK(w.get<std::string>().find("moved onto") == std::string::npos);
}

TEST_CASE("probe command line: names with spaces and quotes stay one shell word, numbers read back exactly") {
    CHECK(app::shellQuoted("left wall") == "'left wall'");
    CHECK(app::shellQuoted("it's") == "'it'\\''s'");
    CHECK(app::shellQuoted("cornell-box") == "cornell-box");
    CHECK(shellWords("a 'b c' 'it'\\''s'") == std::vector<std::string>{"a", "b c", "it's"});
    for (const double v : {0.1, -0.5554999999999999, 1.0 / 3.0, 1e-300, -0.0}) {
        const std::string text = app::roundTripNumber(v);
        CHECK(std::strtod(text.c_str(), nullptr) == v);
    }
    CHECK(app::roundTripNumber(-0.0) == "0");
}

} // TEST_SUITE
