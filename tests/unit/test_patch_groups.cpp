// Patches grouped into unknowns of about the requested area (issue #20 item 5, step B): on curved,
// finely tessellated surfaces the group count follows the requested area, every patch is in one
// group and the area is kept; the grouped system keeps the physics, gathered (Gauss-Seidel) or shot
// (progressive refinement): inside a closed furnace B = E / (1 - rho) on every patch (the closed
// form), and a lit sphere's irradiance per group is the ungrouped solution's over the same patches. Scenes from tests/data/make_grouping_scenes.py.
// ctest-labels: threads
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/GroupedSolver.h"
#include "radiometry/solver/SolverFactories.h"
#include "radiometry/solver/Solver.h"
#include "tests/support/MeshTopology.h"
#include "tests/support/Relative.h"
#include "tests/support/RunRadiant.h"

using namespace radiant;
using radiant::test::relativeTo;

namespace {

Scene loadGrouping(const std::string& file) {
    return loadScene(std::string(RADIANT_TEST_DATA_DIR) + "/grouping/" + file).scene;
}

PatchMesh meshPatchGroups(const Scene& scene, double area) {
    MeshingOptions options;
    options.maxPatchArea = area;
    return meshScene(scene, options);
}

PatchGroups groupAt(const PatchMesh& mesh, double area) {
    GroupingOptions options;
    options.maxGroupArea = area;
    return groupPatches(mesh, options);
}

/// Every patch in exactly one group, within its surface, under the area, and the groups' areas
/// their patches' sums; every group edge-connected.
void checkPartition(const PatchMesh& mesh, const PatchGroups& groups, double maxArea) {
    REQUIRE(groups.groupOf.size() == mesh.size());
    REQUIRE(groups.members.size() == mesh.size());
    std::vector<int> seen(mesh.size(), 0);
    for (std::size_t s = 0; s + 1 < mesh.surfaceFirstPatch.size(); ++s)
        for (std::uint32_t g = groups.surfaceFirstGroup[s]; g < groups.surfaceFirstGroup[s + 1]; ++g) {
            double area = 0;
            for (const std::uint32_t p : groups.patchesOf(g)) {
                ++seen[p];
                CHECK(groups.groupOf[p] == g);
                CHECK(mesh.patches[p].surface == s);
                area += mesh.patches[p].area;
            }
            CHECK(groups.area[g] == relativeTo(area, 1e-12));
            CHECK(groups.area[g] <= maxArea * (1 + 1e-5));
        }
    CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

std::size_t groupsOf(const PatchGroups& groups, std::size_t surface) {
    return groups.surfaceFirstGroup[surface + 1] - groups.surfaceFirstGroup[surface];
}

/// Inside a closed convex surface emitting 1 and reflecting rho everywhere (no visibility rays: it
/// sees itself whole), the grouped system must give B = 1 / (1 - rho) on every patch, with its rows
/// (including a curved group's F_CC) summing to 1 to the quadrature's accuracy.
void checkGroupedFurnace(const Scene& scene, const PatchMesh& mesh, std::shared_ptr<const PatchGroups> groups, double rho) {
    const FormFactorMatrix matrix = computeGroupedFormFactors(mesh, *groups, nullptr, {.visibilityRays = 0}, 1e-7);
    REQUIRE(matrix.size() == groups->size());
    double deviation = 0, selfMost = 0;
    for (std::size_t c = 0; c < matrix.size(); ++c) {
        deviation = std::max(deviation, std::abs(matrix.rowSum(c) - 1));
        for (const FormFactorEntry& e : matrix.row(c))
            if (e.column == c) selfMost = std::max(selfMost, static_cast<double>(e.value));
    }
    MESSAGE(mesh.size() << " patches in " << groups->size() << " groups, row sums within " << deviation
                        << " of 1, largest F_CC " << selfMost);
    REQUIRE(deviation < 1e-2);
    SolverOptions options;
    options.formFactors.visibilityRays = 0;
    auto solver = makeGroupedSolver(SolverMethod::GaussSeidel, scene, mesh, groups, options);
    for (int k = 0; k < 1000 && solver->step().residual > 1e-9; ++k) {
    }
    const double expected = 1 / (1 - rho);
    const double tolerance = rho * deviation / (1 - rho * (1 + deviation)) + 1e-5;
    REQUIRE(solver->solution().size() == mesh.size());
    double absorbed = 0, emitted = 0;
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        CHECK(solver->solution()[p].x == relativeTo(expected, tolerance));
        absorbed += (1 - rho) * mesh.patches[p].area * solver->solution()[p].x;
        emitted += mesh.patches[p].area;
    }
    CHECK(absorbed == relativeTo(emitted, deviation + 1e-5));
}

/// The same furnace solved by grouped progressive refinement (makeGroupedSolver's shots): the
/// shots' columns F_DC, all of them, must give every group's row sum 1 to the kernels' accuracy,
/// and the shooting must converge to B = 1 / (1 - rho) on every patch with the power absorbed that
/// was emitted. With visibility rays too: inside a convex furnace every ray between a receiver and a
/// curved group's members must get through (none caught on the group's own facets near its ends).
void checkProgressiveFurnace(const Scene& scene, const PatchMesh& mesh, std::shared_ptr<const PatchGroups> groups,
                             double rho, int visibilityRays) {
    SolverOptions options;
    options.formFactors.visibilityRays = visibilityRays;
    // Blocks of one cell: every group shoots alone, with its patch's polygon if it has one patch.
    const ProgressiveShooters shooters = groupShooters(mesh, *groups, 1);
    REQUIRE(shooters.size() == groups->size());
    const GroupShotFormFactors shot = makeRayCastPatchGroupShotFormFactors(scene, mesh, groups, shooters, options);
    std::vector<double> rowSum(groups->size(), 0.0);
    std::vector<Rgb> column(groups->size());
    for (std::size_t c = 0; c < shooters.size(); ++c) {
        shot(c, 0, std::vector<Rgb>{Rgb(1.0 / 3)}, 1.0, column);
        for (std::size_t d = 0; d < groups->size(); ++d) rowSum[d] += column[d].x;
    }
    double deviation = 0;
    for (const double sum : rowSum) deviation = std::max(deviation, std::abs(sum - 1));
    MESSAGE(mesh.size() << " patches in " << groups->size() << " groups, " << visibilityRays
                        << " rays: shot row sums within " << deviation << " of 1");
    REQUIRE(deviation < 1e-2);

    auto solver = makeGroupedSolver(SolverMethod::Progressive, scene, mesh, groups, options);
    CHECK(solver->method() == SolverMethod::Progressive);
    std::size_t shots = 0;
    while (solver->lastStats().residual > 1e-9 && shots < 20000) {
        const IterationStats stats = solver->step();
        ++shots;
        REQUIRE(stats.shooter >= 0);  // a patch of the shooting group
        REQUIRE(static_cast<std::size_t>(stats.shooter) < mesh.size());
    }
    MESSAGE(shots << " shots to unshot power 1e-9");
    REQUIRE(solver->lastStats().residual <= 1e-9);
    const double expected = 1 / (1 - rho);
    const double tolerance = rho * deviation / (1 - rho * (1 + deviation)) + 1e-5;
    REQUIRE(solver->solution().size() == mesh.size());
    double absorbed = 0, emitted = 0, worst = 0;
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        const double b = solver->solution()[p].x;
        worst = std::max(worst, std::abs(b / expected - 1));
        CHECK(b == relativeTo(expected, tolerance));
        absorbed += (1 - rho) * mesh.patches[p].area * b;
        emitted += mesh.patches[p].area;
    }
    MESSAGE("worst patch off B = E / (1 - rho) by " << worst);
    CHECK(absorbed == relativeTo(emitted, deviation + 1e-5));
}

} // namespace

TEST_CASE("rounded cube and sphere of thousands of triangles: groups follow the requested area") {
    struct Case {
        const char* file;
        const char* surface;
    };
    for (const Case c : {Case{"rounded_cube_room.gltf", "rounded cube"}, Case{"sphere_room.gltf", "sphere"}}) {
        const Scene scene = loadGrouping(c.file);
        const std::size_t surface = scene.findSurface(c.surface);
        for (const double area : {0.05, 0.2, 1.0}) {
            const std::string file = c.file;
            CAPTURE(file);
            CAPTURE(area);
            const PatchMesh mesh = meshPatchGroups(scene, area);
            const PatchGroups groups = groupAt(mesh, area);
            checkPartition(mesh, groups, area);
            const double total = radiant::test::surfacePatchArea(mesh, surface);
            const double ideal = total / area;
            const auto count = static_cast<double>(groupsOf(groups, surface));
            MESSAGE(std::string(c.surface) << " at " << area << " m^2: " << mesh.surfaceFirstPatch[surface + 1] - mesh.surfaceFirstPatch[surface]
                              << " patches, " << count << " groups, area / max " << ideal);
            // At least the area's count; at most twice it, or twice what the normal spread needs
            // where that is more: a group is at most a cap of the spread's half-angle, a fraction
            // (1 - cos) / 2 of a sphere's directions (4 caps of 60 degrees; a cube's 6 sides).
            const double spread = GroupingOptions{}.spreadDegrees * std::numbers::pi / 180;
            const double spreadNeeds = 2 / (1 - std::cos(spread));
            CHECK(count >= std::floor(ideal));
            CHECK(count <= 2 * std::max(ideal, spreadNeeds));
        }
    }
}

TEST_CASE("groups stop at creases and at a spread of normals") {
    const Scene scene = loadGrouping("cylinder_room.gltf");
    const PatchMesh mesh = meshPatchGroups(scene, 1.0);
    const PatchGroups groups = groupAt(mesh, 10.0);
    checkPartition(mesh, groups, 10.0);
    const std::size_t cylinder = scene.findSurface("cylinder");
    // The caps meet the side at 90 degrees: no group holds both. The side turns through 360
    // degrees, so it needs at least 360 / 120 groups of at most 60 degrees either side of their seed.
    std::size_t caps = 0, sides = 0;
    for (std::uint32_t g = groups.surfaceFirstGroup[cylinder]; g < groups.surfaceFirstGroup[cylinder + 1]; ++g) {
        std::size_t capPatches = 0;
        for (const std::uint32_t p : groups.patchesOf(g)) capPatches += std::abs(mesh.patches[p].normal.y) > 0.999;
        CHECK((capPatches == 0 || capPatches == groups.patchesOf(g).size()));
        (capPatches == 0 ? sides : caps) += 1;
    }
    CHECK(caps == 2);
    CHECK(sides >= 3);
    CHECK(sides <= 6);
    CHECK_THROWS_AS(groupAt(mesh, 0.0), RadiantError);
}

TEST_CASE("ungrouped patches are the patch system itself") {
    const Scene scene = loadGrouping("sphere_room.gltf");
    const PatchMesh mesh = meshPatchGroups(scene, 0.5);
    const PatchGroups groups = ungroupedPatches(mesh);
    checkPartition(mesh, groups, 0.5);
    CHECK(groups.size() == mesh.size());
}

TEST_CASE("furnace inside a grouped tessellated sphere: B = E / (1 - rho) on every patch") {
    const Scene scene = loadGrouping("furnace_sphere.gltf");  // radius 1: 12.6 m^2 in 960 triangles
    const PatchMesh mesh = meshPatchGroups(scene, 1.0);
    auto groups = std::make_shared<const PatchGroups>(groupAt(mesh, 1.0));
    CHECK(static_cast<double>(groups->size()) <= 2 * 4 * 3.14159265 / 1.0);
    checkGroupedFurnace(scene, mesh, groups, 0.5);
}

TEST_CASE("furnace inside a grouped bevelled box: B = E / (1 - rho) on every patch") {
    const Scene scene = loadGrouping("bevelled_box_furnace.gltf");
    const PatchMesh mesh = meshPatchGroups(scene, 0.2);
    auto groups = std::make_shared<const PatchGroups>(groupAt(mesh, 0.2));
    checkGroupedFurnace(scene, mesh, groups, 0.5);
}

TEST_CASE("grouped progressive refinement: furnaces inside the grouped sphere and bevelled box give B = E / (1 - rho)") {
    {
        const Scene scene = loadGrouping("furnace_sphere.gltf");
        const PatchMesh mesh = meshPatchGroups(scene, 1.0);
        auto groups = std::make_shared<const PatchGroups>(groupAt(mesh, 1.0));
        checkProgressiveFurnace(scene, mesh, groups, 0.5, 0);
        checkProgressiveFurnace(scene, mesh, groups, 0.5, 16);
    }
    {
        const Scene scene = loadGrouping("bevelled_box_furnace.gltf");
        const PatchMesh mesh = meshPatchGroups(scene, 0.2);
        auto groups = std::make_shared<const PatchGroups>(groupAt(mesh, 0.2));
        checkProgressiveFurnace(scene, mesh, groups, 0.5, 0);
        checkProgressiveFurnace(scene, mesh, groups, 0.5, 16);
    }
}

TEST_CASE("a lit grouped sphere gathers what the ungrouped sphere gathers over the same patches, shot or gathered") {
    const Scene scene = loadGrouping("sphere_room.gltf");
    const std::size_t sphere = scene.findSurface("sphere");
    const double area = 0.25;
    const PatchMesh mesh = meshPatchGroups(scene, area);
    auto groups = std::make_shared<const PatchGroups>(groupAt(mesh, area));
    SolverOptions options;
    options.formFactors.visibilityRays = 16;  // the sphere shadows the floor
    auto grouped = makeGroupedSolver(SolverMethod::GaussSeidel, scene, mesh, groups, options);
    auto ungrouped = makeGaussSeidelSolver(scene, mesh, options, nullptr);
    auto shooting = makeGroupedSolver(SolverMethod::Progressive, scene, mesh, groups, options);
    for (Solver* solver : {grouped.get(), ungrouped.get()})
        for (int k = 0; k < 1000 && solver->step().residual > 1e-7; ++k) {
        }
    for (int k = 0; k < 100000 && shooting->step().residual > 1e-6; ++k) {
    }
    MESSAGE("sphere: " << mesh.surfaceFirstPatch[sphere + 1] - mesh.surfaceFirstPatch[sphere] << " patches in "
                       << groupsOf(*groups, sphere) << " groups");
    // The sphere is convex and emits nothing, so its B = rho E. A group's E is the area-weighted mean
    // of its patches' E with B held constant over each other group: with the lamp and the walls
    // ungrouped-sized, only light that left the sphere and came back differs.
    const double rho = 0.5;
    double largest = 0, largestShot = 0, poweredGrouped = 0, poweredShot = 0, poweredUngrouped = 0;
    for (std::uint32_t g = groups->surfaceFirstGroup[sphere]; g < groups->surfaceFirstGroup[sphere + 1]; ++g) {
        double power = 0;
        for (const std::uint32_t p : groups->patchesOf(g)) power += mesh.patches[p].area * ungrouped->solution()[p].x;
        const double ungroupedE = power / groups->area[g] / rho;
        const double groupedE = grouped->solution()[groups->patchesOf(g)[0]].x / rho;
        const double shotE = shooting->solution()[groups->patchesOf(g)[0]].x / rho;
        largest = std::max(largest, std::abs(groupedE / ungroupedE - 1));
        largestShot = std::max(largestShot, std::abs(shotE / ungroupedE - 1));
        CHECK(groupedE == relativeTo(ungroupedE, 0.01));
        // Progressive refinement computes the same F_CD by its own quadrature: shots from the
        // receiving patches' Gauss points and fresh visibility rays per shot.
        CHECK(shotE == relativeTo(ungroupedE, 0.02));
        poweredGrouped += groups->area[g] * groupedE;
        poweredShot += groups->area[g] * shotE;
        poweredUngrouped += power / rho;
    }
    MESSAGE("largest relative difference of a group's irradiance: " << largest << " gauss-seidel, " << largestShot
                                                                     << " progressive");
    CHECK(poweredGrouped == relativeTo(poweredUngrouped, 0.002));
    CHECK(poweredShot == relativeTo(poweredUngrouped, 0.01));
}

TEST_CASE("radiant solve --group-patches shoots the groups by default, reports them as the unknowns, and hierarchical solves the patches") {
    const std::string file = "'" + std::string(RADIANT_TEST_DATA_DIR) + "/grouping/sphere_room.gltf'";
    const test::CommandRun run = test::runRadiant("solve " + file + " --group-patches --max-patch-area 1 --json -");
    INFO(run.err);
    REQUIRE(run.status == 0);
    const nlohmann::json report = nlohmann::json::parse(run.out);
    CHECK(report["method"] == "progressive");
    CHECK(run.err.find("radiant: method: progressive (567 patches in 63 groups: progressive refinement over the groups") !=
          std::string::npos);
    CHECK(report["unknowns"].get<std::size_t>() < report["patches"].get<std::size_t>());
    const nlohmann::json& sphere = report["surfaces"].back();
    REQUIRE(sphere["name"] == "sphere");
    CHECK(sphere["patches"] == 512);
    CHECK(sphere["unknowns"].get<std::size_t>() <= 8);  // 3.1 m^2 at 1 m^2, the spread needs 4

    // Hierarchical takes no groups: it solves the patches and says so (test_default_grouping.cpp).
    const test::CommandRun hierarchical =
        test::runRadiant("solve " + file + " --group-patches --method hierarchical --max-patch-area 1 --max-iterations 1");
    CHECK(hierarchical.status == 0);
    CHECK(hierarchical.err.find("radiant: grouping: off: hierarchical refines its own elements and takes no groups") !=
          std::string::npos);
}

TEST_CASE("grouped, the default method counts the groups, not the patches") {
    // The rounded cube's room at 1 m^2: 3,103 patches, above progressive refinement's 3,000, so
    // hierarchical ungrouped; 75 groups, so progressive refinement grouped. Only the choice is run.
    const std::string file = "'" + std::string(RADIANT_TEST_DATA_DIR) + "/grouping/rounded_cube_room.gltf'";
    const test::CommandRun plain =
        test::runRadiant("solve " + file + " --no-group-patches --max-patch-area 1 --max-iterations 1 --json -");
    const test::CommandRun grouped =
        test::runRadiant("solve " + file + " --group-patches --max-patch-area 1 --max-iterations 1 --json -");
    INFO(plain.err);
    INFO(grouped.err);
    REQUIRE(plain.status == 0);
    REQUIRE(grouped.status == 0);
    CHECK(nlohmann::json::parse(plain.out)["method"] == "hierarchical");
    const nlohmann::json report = nlohmann::json::parse(grouped.out);
    CHECK(report["method"] == "progressive");
    CHECK(report["patches"] == 3103);
    CHECK(report["unknowns"] == 75);
    CHECK(report["method_reason"].get<std::string>().find("3,103 patches in 75 groups") != std::string::npos);
}
