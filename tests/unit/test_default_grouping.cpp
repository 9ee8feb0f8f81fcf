// ctest-labels: threads
// Grouping by default where it pays (#20 item 5): a surface tessellated finer than the requested
// patch area is grouped into unknowns of about that area without a flag, in `solve`, `probe`,
// `render` and the lab alike (chooseSystem); scenes of large quads (the built-in scenes) are never
// grouped; --no-group-patches gives the patches back; a method that takes no groups solves the
// patches and says so; the lab opens a room at about the Cornell box's patch count. Scenes from
// tests/data/make_grouping_scenes.py.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/solver/SolverThread.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/DefaultGrouping.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/GroupedSolver.h"
#include "radiometry/solver/OpeningPatchArea.h"
#include "radiometry/solver/SolveDefaults.h"
#include "tests/support/Relative.h"
#include "tests/support/RunRadiant.h"
#include "tests/support/Common.h"

using namespace radiant;
using radiant::test::relativeTo;

namespace {

std::string groupingFile(const std::string& name) { return std::string(RADIANT_TEST_DATA_DIR) + "/grouping/" + name; }

using radiant::test::contains;

PatchMesh meshGrouped(const Scene& scene, double area) {
    MeshingOptions options;
    options.maxPatchArea = area;
    return meshScene(scene, options);
}

const nlohmann::json& surfaceNamed(const nlohmann::json& report, const std::string& name) {
    for (const nlohmann::json& surface : report["surfaces"])
        if (surface["name"] == name) return surface;
    FAIL("no surface " << name);
    return report;
}

} // namespace

TEST_CASE("the built-in scenes of large quads are never grouped by default: the same patches, unknowns and method") {
    for (const std::string& name : builtinSceneNames()) {
        const Scene scene = makeBuiltinScene(name);
        // The command line's default, the lab's opening areas, the GL tests' coarse meshes, the
        // stress test's, the slider's end and beyond.
        for (const double area : {kSolveDefaults.maxPatchArea, 0.002, 0.0025, 0.005, 0.01, 0.05, 0.12, 0.25, 1.0}) {
            CAPTURE(name);
            CAPTURE(area);
            const PatchMesh mesh = meshGrouped(scene, area);
            const SystemChoice choice = chooseSystem(mesh, area, GroupingMode::Auto, std::nullopt);
            INFO(choice.groupingReason);
            CHECK_FALSE(choice.groups);
            CHECK(contains(choice.groupingReason, "off: no surface is tessellated finer"));
            const MethodChoice plain = chooseDefaultMethod(mesh.size());
            CHECK(choice.method.method == plain.method);
            CHECK(choice.method.reason == plain.reason);
        }
    }
    // The Cornell box keeps its patch count: the accuracy table's and the lab's 2,248.
    CHECK(meshGrouped(makeCornellBox(), kSolveDefaults.maxPatchArea).size() == 2248);
    // Its stderr is what it was (the method's line only); the JSON says why nothing was grouped.
    const test::CommandRun run = test::runRadiant("solve cornell-box --max-patch-area 0.05 --max-iterations 1 --json -");
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK_FALSE(contains(run.err, "radiant: grouping:"));
    const nlohmann::json report = nlohmann::json::parse(run.out);
    CHECK(report["grouped"] == false);
    CHECK(report["unknowns"] == report["patches"]);
    CHECK(contains(report["grouping_reason"].get<std::string>(), "off: no surface is tessellated finer than 0.05 m^2 (500 cm^2)"));
}

TEST_CASE("radiant solve groups a finely tessellated object by default: unknowns near its area over --max-patch-area") {
    struct Case {
        const char* file;
        const char* object;
        std::size_t patches;  // ungrouped at 1 m^2 (the object; the README's counts)
    };
    for (const Case c : {Case{"bevelled_box_room.gltf", "bevelled box", 246}, Case{"cylinder_room.gltf", "cylinder", 114},
                         Case{"sphere_room.gltf", "sphere", 512}, Case{"rounded_cube_room.gltf", "rounded cube", 3048}}) {
        const std::string object = c.object;
        CAPTURE(object);
        const std::string file = "'" + groupingFile(c.file) + "'";
        const test::CommandRun grouped = test::runRadiant("solve " + file + " --max-patch-area 1 --json -");
        INFO(grouped.err);
        REQUIRE(grouped.status == 0);
        const nlohmann::json report = nlohmann::json::parse(grouped.out);
        CHECK(report["grouped"] == true);
        CHECK(report["method"] == "progressive");
        const std::string reason = report["grouping_reason"].get<std::string>();
        CHECK(contains(reason, "on: "));
        CHECK(contains(reason, "1 of 8 surfaces tessellated finer than 1 m^2"));
        CHECK(contains(grouped.err, "radiant: grouping: " + reason));
        const nlohmann::json& surface = surfaceNamed(report, c.object);
        CHECK(surface["patches"] == c.patches);
        const double perArea = surface["area_m2"].get<double>() / 1.0;
        const auto unknowns = surface["unknowns"].get<double>();
        MESSAGE(object << ": " << c.patches << " patches in " << unknowns << " groups, area / A = " << perArea);
        // Between area / A (each group at most A) and twice it, or twice the 4 a group's 60-degree
        // spread needs on a sphere.
        CHECK(unknowns >= std::floor(perArea));
        CHECK(unknowns <= std::max(2 * perArea, 8.0));
        // The room's walls (9 m^2 each, 9 patches at 1 m^2) stay one patch an unknown.
        CHECK(surfaceNamed(report, "floor")["unknowns"] == 9);

        const test::CommandRun plain = test::runRadiant("solve " + file + " --max-patch-area 1 --no-group-patches --json -");
        INFO(plain.err);
        REQUIRE(plain.status == 0);
        const nlohmann::json old = nlohmann::json::parse(plain.out);
        CHECK(old["grouped"] == false);
        CHECK(old["patches"] == report["patches"]);
        CHECK(old["unknowns"] == old["patches"]);
        CHECK(surfaceNamed(old, c.object)["unknowns"] == c.patches);
        CHECK_FALSE(contains(plain.err, "radiant: grouping:"));  // asked for: nothing to explain
    }
}

TEST_CASE("the default grouping keeps B = E / (1 - rho) inside the bevelled box furnace, on every patch, within 0.2%") {
    const Scene scene = loadScene(groupingFile("bevelled_box_furnace.gltf")).scene;
    const double area = 1.0;
    const PatchMesh mesh = meshGrouped(scene, area);
    const SystemChoice choice = chooseSystem(mesh, area, GroupingMode::Auto, std::nullopt);
    INFO(choice.groupingReason);
    REQUIRE(choice.groups);
    CHECK(choice.method.method == SolverMethod::Progressive);
    const double perArea = mesh.totalArea() / area;
    MESSAGE(mesh.size() << " patches in " << choice.groups->size() << " groups by default, area / A = " << perArea);
    CHECK(static_cast<double>(choice.groups->size()) >= std::floor(perArea));
    CHECK(static_cast<double>(choice.groups->size()) <= 2 * perArea);
    // As `radiant solve` builds it: progressive refinement over the groups, visibility rays on.
    auto solver = makeGroupedSolver(choice.method.method, scene, mesh, choice.groups, SolverOptions{});
    std::size_t shots = 0;
    while (solver->lastStats().residual > 1e-7 && shots < 20000) {
        (void)solver->step();
        ++shots;
    }
    REQUIRE(solver->lastStats().residual <= 1e-7);
    const double expected = 1 / (1 - 0.5);  // E = 1 W/m^2, rho = 0.5 (make_grouping_scenes.py)
    double worst = 0;
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        const double b = solver->solution()[p].x;
        worst = std::max(worst, std::abs(b / expected - 1));
        CHECK(b == relativeTo(expected, 0.002));
    }
    MESSAGE(shots << " shots; worst patch off B = E / (1 - rho) by " << worst);
}

TEST_CASE("an explicit method that takes no groups solves the patches and says so, never an error") {
    const std::string file = "'" + groupingFile("sphere_room.gltf") + "'";
    for (const std::string flags : {"", " --group-patches"}) {
        CAPTURE(flags);
        const test::CommandRun run =
            test::runRadiant("solve " + file + flags + " --method hierarchical --max-patch-area 1 --max-iterations 2 --json -");
        INFO(run.err);
        REQUIRE(run.status == 0);
        const nlohmann::json report = nlohmann::json::parse(run.out);
        CHECK(report["method"] == "hierarchical");
        CHECK(report["grouped"] == false);
        CHECK(report["unknowns"] == report["patches"]);
        const std::string reason = report["grouping_reason"].get<std::string>();
        CHECK(contains(reason, "off: hierarchical refines its own elements and takes no groups (567 patches in"));
        CHECK(contains(run.err, "radiant: grouping: " + reason + "\n"));
    }
    // The probe's JSON and stderr alike.
    const test::CommandRun probe = test::runRadiant("probe " + file +
                                                    " --point 0,0.001,1 --normal 0,1,0 --method importance "
                                                    "--max-patch-area 1 --max-iterations 2");
    INFO(probe.err);
    REQUIRE(probe.status == 0);
    const nlohmann::json reading = nlohmann::json::parse(probe.out);
    CHECK(reading["grouped"] == false);
    CHECK(contains(reading["grouping_reason"].get<std::string>(), "off: importance refines its own elements"));
    CHECK(contains(probe.err, "radiant: grouping: off: importance"));

    // Without a method, the probe groups as solve does.
    const test::CommandRun defaulted =
        test::runRadiant("probe " + file + " --point 0,0.001,1 --normal 0,1,0 --max-patch-area 1");
    INFO(defaulted.err);
    REQUIRE(defaulted.status == 0);
    const nlohmann::json grouped = nlohmann::json::parse(defaulted.out);
    CHECK(grouped["grouped"] == true);
    CHECK(grouped["unknowns"] == 63);
    CHECK(grouped["method"] == "progressive");
}

TEST_CASE("--group-patches and --no-group-patches exclude each other") {
    const test::CommandRun run =
        test::runRadiant("solve cornell-box --group-patches --no-group-patches --max-patch-area 0.05");
    CHECK(run.status == 2);
    CHECK(contains(run.err, "excludes"));
}

TEST_CASE("the lab opens a room within progressive refinement's patch count, and the Cornell box at the default") {
    const OpeningArea cornell = openingPatchArea(makeCornellBox());
    CHECK(cornell.maxPatchArea == kSolveDefaults.maxPatchArea);
    CHECK(contains(cornell.reason, "the default: 2,248 patches"));
    // The shipped Cornell box file (float positions) too.
    CHECK(openingPatchArea(loadScene("cornell-box").scene).maxPatchArea == kSolveDefaults.maxPatchArea);

    const Scene room = loadScene(groupingFile("sphere_room.gltf")).scene;
    const OpeningArea opening = openingPatchArea(room);
    INFO(opening.reason);
    // 46,849 patches at 13 cm^2, 3,441 at 200 cm^2, 2,694 at 250 cm^2: the first step within 3,000.
    CHECK(opening.maxPatchArea == relativeTo(0.025, 1e-12));
    CHECK(contains(opening.reason, "250 cm^2 for the scene's "));
    CHECK(contains(opening.reason, "2,694 patches, within the 3,000 progressive refinement solves by default (13 cm^2 would make 46,849)"));
    const PatchMesh mesh = meshGrouped(room, opening.maxPatchArea);
    CHECK(mesh.size() == 2694);
    const SystemChoice choice = chooseSystem(mesh, opening.maxPatchArea, GroupingMode::Auto, std::nullopt);
    CHECK(choice.method.method == SolverMethod::Progressive);
    // The coarsest opening is the slider's end.
    Scene huge = room;
    for (Surface& surface : huge.surfaces)
        for (Face& face : surface.faces) {
            for (glm::dvec3& v : face.vertices) v *= 100.0;
            face.updateGeometry();
        }
    CHECK(openingPatchArea(huge).maxPatchArea == kMaxOpeningPatchArea);
}

TEST_CASE("the lab groups as the command line does: by default where it pays, off with the box, and a picked hierarchical solves the patches") {
    using namespace radiant::app;
    auto scene = std::make_shared<const Scene>(loadScene(groupingFile("sphere_room.gltf")).scene);
    SolverThread thread;
    thread.send(command::LoadScene{scene, MeshingOptions{1.0}});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    REQUIRE(snapshot->groups);
    CHECK(snapshot->groups->size() == 63);  // as `radiant solve --max-patch-area 1`
    CHECK(contains(snapshot->groupingReason, "on: 567 patches in 63 groups"));
    CHECK_FALSE(snapshot->methodTakesNoGroups);

    thread.send(command::SetMethod{SolverMethod::Hierarchical});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK(snapshot->method == SolverMethod::Hierarchical);
    CHECK_FALSE(snapshot->groups);
    CHECK(snapshot->methodTakesNoGroups);
    CHECK(contains(snapshot->groupingReason, "hierarchical refines its own elements and takes no groups"));

    thread.send(command::SetMethod{SolverMethod::GaussSeidel});  // takes groups again
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    REQUIRE(snapshot->groups);
    CHECK(snapshot->groups->size() == 63);
    CHECK_FALSE(snapshot->methodTakesNoGroups);

    thread.send(command::SetGrouping{GroupingMode::Off});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK_FALSE(snapshot->groups);
    CHECK(contains(snapshot->groupingReason, "off, as asked"));
}
