// Meshing: areas are kept, patches stay under the requested size, the mesh is conforming within a
// surface (no T-junctions; Euler characteristic of each surface's topology), budgets are refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchLocator.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "tests/support/MeshTopology.h"

using namespace radiant;
using radiant::test::countTJunctions;
using radiant::test::eulerCharacteristic;
using radiant::test::makeFace;
using radiant::test::sceneOf;

namespace {

using radiant::test::surfacePatchArea;

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("a rectangle becomes an n x m grid of equal quads sharing their vertices") {
    // 2 m x 1 m at 0.01 m^2: cells of 0.1 m, so 20 x 10 quads on a 21 x 11 lattice.
    for (const auto& [w, h, maxArea] : {std::tuple{2.0, 1.0, 0.01}, std::tuple{0.3, 0.7, 0.0025}, std::tuple{1.0, 1.0, 1.0}}) {
        const Scene scene = sceneOf({makeFace({{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}})});
        const PatchMesh mesh = meshScene(scene, {maxArea * (1 + 1e-6)});
        const auto nu = static_cast<std::size_t>(std::lround(w / std::sqrt(maxArea)));
        const auto nv = static_cast<std::size_t>(std::lround(h / std::sqrt(maxArea)));
        CHECK(mesh.size() == nu * nv);
        CHECK(mesh.vertices.size() == (nu + 1) * (nv + 1));
        for (const Patch& p : mesh.patches) {
            CHECK(p.cornerCount == 4);
            CHECK(p.area == doctest::Approx(w * h / static_cast<double>(nu * nv)).epsilon(1e-9).scale(0));
            CHECK(p.normal.z == doctest::Approx(1.0).scale(0));
        }
        CHECK(eulerCharacteristic(mesh, 0) == 1);
    }
}

TEST_CASE("a triangle becomes n^2 similar triangles on (n+1)(n+2)/2 shared vertices") {
    for (const std::size_t n : {1u, 2u, 4u, 7u}) {
        const Scene scene = sceneOf({makeFace({{0, 0, 0}, {1, 0, 0}, {0, 0, -1}})});  // area 1/2, normal +y
        const double maxArea = 0.5 / static_cast<double>(n * n) * 1.0001;
        const PatchMesh mesh = meshScene(scene, {maxArea});
        CHECK(mesh.size() == n * n);
        CHECK(mesh.vertices.size() == (n + 1) * (n + 2) / 2);
        for (const Patch& p : mesh.patches) {
            CHECK(p.cornerCount == 3);
            CHECK(p.area == doctest::Approx(0.5 / static_cast<double>(n * n)).epsilon(1e-9).scale(0));
            CHECK(p.normal.y == doctest::Approx(1.0).scale(0));  // orientation kept
        }
        CHECK(eulerCharacteristic(mesh, 0) == 1);
    }
}

TEST_CASE("Cornell box: areas kept, every patch under the limit, no T-junctions") {
    const Scene cornell = makeCornellBox();
    for (const double maxArea : {1e-2, 1e-3, 1e-4}) {
        CAPTURE(maxArea);
        const PatchMesh mesh = meshScene(cornell, {maxArea});
        REQUIRE(mesh.surfaceFirstPatch.size() == cornell.surfaces.size() + 1);
        CHECK(mesh.surfaceFirstPatch.back() == mesh.size());
        CHECK(mesh.totalArea() == doctest::Approx(cornell.totalArea()).epsilon(1e-9).scale(0));
        double smallest = 1e30;
        for (const Patch& p : mesh.patches) {
            CHECK(p.area <= maxArea * (1 + 4e-6));
            // The floor is cut along the blocks' footprints (ContactCuts.h), into pieces of any size.
            if (cornell.surfaces[p.surface].name != "floor") smallest = std::min(smallest, p.area);
        }
        // Sized to the limit, not needlessly fine: no patch below a fifth of it.
        CHECK(smallest > maxArea / 5);
        for (std::size_t s = 0; s < cornell.surfaces.size(); ++s) {
            CAPTURE(cornell.surfaces[s].name);
            CHECK(surfacePatchArea(mesh, s) == doctest::Approx(cornell.surfaces[s].area()).epsilon(1e-9).scale(0));
            for (std::size_t p = mesh.surfaceFirstPatch[s]; p < mesh.surfaceFirstPatch[s + 1]; ++p)
                CHECK(mesh.patches[p].surface == s);
        }
        CHECK(estimatePatchCount(cornell, {maxArea}) == mesh.size());
    }
    // The floor is a trapezoid: (552.8 + 549.6) / 2 x 559.2 mm^2, from the published corners.
    const PatchMesh coarse = meshScene(cornell, {0.01});
    CHECK(surfacePatchArea(coarse, cornell.findSurface("floor")) ==
          doctest::Approx((0.5528 + 0.5496) / 2 * 0.5592).epsilon(1e-9).scale(0));

    const PatchMesh mesh = meshScene(cornell, {1e-4});  // 1 cm^2
    for (std::size_t s = 0; s < cornell.surfaces.size(); ++s) {
        CAPTURE(cornell.surfaces[s].name);
        CHECK(countTJunctions(mesh, s, 0.01) == 0);
        // Topology: the ceiling is a ring around the light, every other surface a disc (the blocks
        // are open boxes without a bottom). Seams that did not share vertices would add one each.
        CHECK(eulerCharacteristic(mesh, s) == (cornell.surfaces[s].name == "ceiling" ? 0 : 1));
    }
    // Vertices are not shared between surfaces (radiosity jumps there).
    std::vector<std::size_t> owner(mesh.vertices.size(), cornell.surfaces.size());
    bool shared = false;
    for (const Patch& p : mesh.patches)
        for (std::size_t i = 0; i < p.cornerCount; ++i) {
            std::size_t& o = owner[p.corners[i]];
            if (o != cornell.surfaces.size() && o != p.surface) shared = true;
            o = p.surface;
        }
    CHECK_FALSE(shared);
}

TEST_CASE("a tapered quad is refined until its largest cell fits") {
    // A trapezoid 1 m wide at the base and 0.1 m at the top: its cells near the base are ten times
    // those near the top, so the first guess from the mean edge lengths is too coarse.
    const Scene scene = sceneOf({makeFace({{0, 0, 0}, {1, 0, 0}, {0.55, 1, 0}, {0.45, 1, 0}})});
    for (const double maxArea : {0.1, 0.01, 0.001}) {
        const PatchMesh mesh = meshScene(scene, {maxArea});
        CHECK(mesh.totalArea() == doctest::Approx(0.55).epsilon(1e-9).scale(0));
        for (const Patch& p : mesh.patches) CHECK(p.area <= maxArea * (1 + 4e-6));
        CHECK(eulerCharacteristic(mesh, 0) == 1);
    }
}

TEST_CASE("a convex polygon with more corners is fanned and stays conforming") {
    // A regular hexagon of circumradius r: area 3 sqrt(3)/2 r^2, and a pentagon: 5/2 r^2 sin(72 deg).
    for (const int corners : {5, 6, 7}) {
        Face face;
        for (int i = 0; i < corners; ++i) {
            const double a = 2 * std::numbers::pi * i / corners;
            face.vertices.push_back({std::cos(a), std::sin(a), 0});
        }
        face.updateGeometry();
        const double area = 0.5 * corners * std::sin(2 * std::numbers::pi / corners);
        const PatchMesh mesh = meshScene(sceneOf({face}), {0.01});
        CHECK(mesh.totalArea() == doctest::Approx(area).epsilon(1e-9).scale(0));
        for (const Patch& p : mesh.patches) CHECK(p.area <= 0.01 * (1 + 4e-6));
        CHECK(eulerCharacteristic(mesh, 0) == 1);
        CHECK(countTJunctions(mesh, 0, 0.1) == 0);
    }
}

TEST_CASE("a quad and a triangle sharing an edge agree on its vertices") {
    const Scene scene = sceneOf({makeFace({{0, 0, 0}, {1, 0, 0}, {1, 0.2, 0}, {0, 0.2, 0}}),
                                 makeFace({{0, 0.2, 0}, {1, 0.2, 0}, {0.5, 2.0, 0}})});
    const PatchMesh mesh = meshScene(scene, {0.005});
    CHECK(mesh.totalArea() == doctest::Approx(0.2 + 0.9).epsilon(1e-9).scale(0));
    CHECK(eulerCharacteristic(mesh, 0) == 1);
    CHECK(countTJunctions(mesh, 0, 0.05) == 0);
}

TEST_CASE("the T-junction check sees a T-junction that the input itself has") {
    // Faces that meet with a corner inside another face's edge are not repaired by meshing (the
    // loader and the built-in scenes make whole-edge contacts); the check must see them.
    const Scene scene = sceneOf({makeFace({{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}}),
                                 makeFace({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}),
                                 makeFace({{1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}})});
    const PatchMesh mesh = meshScene(scene, {4.0});
    CHECK(mesh.size() == 3);
    CHECK(countTJunctions(mesh, 0, 0.5) == 1);
    // 8 vertices, 11 edges (the long edge and the two short ones are not shared), 3 faces: 0, not
    // the 1 of a disc.
    CHECK(eulerCharacteristic(mesh, 0) == 0);
}

TEST_CASE("meshing refuses a patch count over the budget before allocating, with the numbers") {
    const Scene cornell = makeCornellBox();
    MeshingOptions options;
    options.maxPatchArea = 1e-7;
    options.patchBudget = 2'000'000;
    // Every patch holds at most 1e-7 m^2, so at least area / 1e-7 patches are needed.
    CHECK(static_cast<double>(estimatePatchCount(cornell, options)) >= cornell.totalArea() / 1e-7);
    try {
        (void)meshScene(cornell, options);
        FAIL("expected BudgetError");
    } catch (const BudgetError& e) {
        const std::string what = e.what();
        CHECK(what.find("meshing at 1e-07 m^2 would make ") != std::string::npos);
        CHECK(what.find("patches; the budget is 2e+06") != std::string::npos);
    }
    // Absurd requests are refused too, not overflowed.
    options.maxPatchArea = 1e-30;
    CHECK_THROWS_AS((void)meshScene(cornell, options), BudgetError);
    for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        options.maxPatchArea = bad;
        CHECK_THROWS_AS((void)meshScene(cornell, options), RadiantError);
    }
}

TEST_CASE("meshing reports progress per face and honours cancellation") {
    const Scene cornell = makeCornellBox();
    Progress progress;
    const PatchMesh mesh = meshScene(cornell, {0.001}, &progress);
    CHECK(progress.total.load() == cornell.faceCount());
    CHECK(progress.done.load() == cornell.faceCount());
    CHECK(progress.fraction() == doctest::Approx(1.0).scale(0));

    Progress cancelled;
    cancelled.cancelRequested = true;
    CHECK_THROWS_AS((void)meshScene(cornell, {0.001}, &cancelled), Cancelled);
}

TEST_CASE("PatchPolygon derives area, normal and the area-weighted centroid") {
    // Trapezoid with parallel sides 2 (y = 0) and 1 (y = 1): centroid height (b + 2a) / (3 (a + b)) = 4/9.
    const std::array<glm::dvec3, 4> trapezoid{{{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}}};
    const PatchPolygon p = PatchPolygon::from(trapezoid);
    CHECK(p.count == 4);
    CHECK(p.area == doctest::Approx(1.5).scale(0));
    CHECK(p.normal.z == doctest::Approx(1.0).scale(0));
    CHECK(p.centroid.x == doctest::Approx(1.0).scale(0));
    CHECK(p.centroid.y == doctest::Approx(4.0 / 9.0).scale(0));
    const std::array<glm::dvec3, 2> line{{{0, 0, 0}, {1, 0, 0}}};
    CHECK_THROWS_AS((void)PatchPolygon::from(line), RadiantError);
}

TEST_CASE("PatchLocator finds the patch under a point on a face") {
    const Scene cornell = makeCornellBox();
    const PatchMesh mesh = meshScene(cornell, {0.001});
    const PatchLocator locator(mesh);
    for (std::size_t p = 0; p < mesh.size(); p += 7) {
        const Patch& patch = mesh.patches[p];
        // A point between the centroid and the first corner lies inside this patch only.
        const glm::dvec3 inside = 0.6 * patch.centroid + 0.4 * mesh.vertices[patch.corners[0]];
        CHECK(locator.find(patch.surface, patch.face, inside) == p);
        CHECK(distanceOutsidePatch(mesh, p, inside) < 0);
    }
    // Just beyond the floor's edge: the nearest patch, which touches that edge.
    const std::uint32_t floor = static_cast<std::uint32_t>(cornell.findSurface("floor"));
    const std::size_t nearest = locator.find(floor, 0, {0.2, 0.0, -1e-9});
    REQUIRE(nearest != PatchLocator::npos);
    CHECK(distanceOutsidePatch(mesh, nearest, {0.2, 0.0, -1e-9}) < 1e-8);
    CHECK(locator.find(floor, 99, {0.2, 0, 0.2}) == PatchLocator::npos);
}

} // TEST_SUITE
