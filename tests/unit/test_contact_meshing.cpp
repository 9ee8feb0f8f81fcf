// Contact-aware meshing (issue 14, radiometry/mesh/ContactCuts.h): a floor with a box standing on it
// is cut along the box's footprint, so no floor patch lies partly under the box. Checked by geometry
// (each patch wholly inside or outside the footprint, area kept, the floor conforming) and by physics:
// in a closed furnace with the box on the floor every open patch reaches B = E / (1 - rho); a patch
// partly under the box gathers over its covered part too and came out low.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ContactCuts.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/mesh/PatchLocator.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/RadiosityInterpolation.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/Solver.h"
#include "render/display/SmoothingGroups.h"
#include "tests/support/MeshTopology.h"
#include "tests/support/Relative.h"

using namespace radiant;
using radiant::test::countTJunctions;
using radiant::test::eulerCharacteristic;
using radiant::test::makeFace;

namespace {

/// The box's footprint on z = 0: a 0.3 m square centred at (0.45, 0.55), turned 20 degrees, so
/// its sides cross the floor's grid lines at an angle.
std::array<glm::dvec3, 4> footprint() {
    const double turn = 20 * std::numbers::pi / 180, half = 0.15;
    const glm::dvec3 centre(0.45, 0.55, 0), u(std::cos(turn), std::sin(turn), 0), v(-std::sin(turn), std::cos(turn), 0);
    return {centre - half * u - half * v, centre + half * u - half * v, centre + half * u + half * v,
            centre - half * u + half * v};
}

/// A 0.3 m high box on the footprint: four sides facing out and a top, no bottom; `sunk` m of it
/// below the floor (as a box placed by eye in Blender), standing on it when 0.
std::vector<Face> boxFaces(double sunk = 0) {
    const auto f = footprint();
    const glm::dvec3 up(0, 0, 0.3), down(0, 0, -sunk);
    std::vector<Face> faces;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 a = f[i] + down, b = f[(i + 1) % 4] + down;
        faces.push_back(makeFace({a, b, b + up, a + up}));
    }
    faces.push_back(makeFace({f[0] + down + up, f[1] + down + up, f[2] + down + up, f[3] + down + up}));
    return faces;
}

/// The unit floor z = 0 facing up, as one quad or as two triangles (as a glTF file stores it).
std::vector<Face> floorFaces(bool triangles) {
    if (!triangles) return {makeFace({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})};
    return {makeFace({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}), makeFace({{0, 0, 0}, {1, 1, 0}, {0, 1, 0}})};
}

/// Signed distance of a floor point into the footprint (positive inside): the least over its sides.
double insideFootprint(const glm::dvec3& p) {
    const auto f = footprint();
    double least = 1e9;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 along = glm::normalize(f[(i + 1) % 4] - f[i]);
        least = std::min(least, glm::dot(glm::cross(glm::dvec3(0, 0, 1), along), p - f[i]));
    }
    return least;
}

Scene grey(std::vector<Surface> surfaces, double exitance) {
    Scene scene;
    scene.name = "box on a floor";
    scene.materials = {{"grey", Rgb{0.5}, ExitanceRgb{Rgb{exitance}}}};
    scene.surfaces = std::move(surfaces);
    return scene;
}

} // namespace

TEST_SUITE("scenes") {

TEST_CASE("a floor is cut along the footprint of a box standing on it or sunk into it: no patch straddles it, area kept, conforming") {
    for (const bool triangles : {false, true})
    for (const double sunk : {0.0, 0.02}) {
        CAPTURE(triangles);
        CAPTURE(sunk);
        const Scene scene = grey({{"floor", 0, floorFaces(triangles), "test"}, {"box", 0, boxFaces(sunk), "test"}}, 0);
        const PatchMesh mesh = meshScene(scene, {0.005});
        double area = 0, inside = 0;
        std::size_t straddling = 0;
        for (std::size_t p = mesh.surfaceFirstPatch[0]; p < mesh.surfaceFirstPatch[1]; ++p) {
            const Patch& patch = mesh.patches[p];
            double deepest = -1e9, shallowest = 1e9;
            for (std::size_t c = 0; c < patch.cornerCount; ++c) {
                const double d = insideFootprint(mesh.vertices[patch.corners[c]]);
                deepest = std::max(deepest, d);
                shallowest = std::min(shallowest, d);
            }
            // Corners within the cut's snap distance of a footprint line count as on it.
            const double snap = detail::kContactSnap * std::sqrt(1 + 1 + 0.3 * 0.3);
            if (deepest > snap && shallowest < -snap) ++straddling;
            area += patch.area;
            if (insideFootprint(patch.centroid) > 0) inside += patch.area;
        }
        CHECK(straddling == 0);
        CHECK(area == radiant::test::relativeTo(1.0, 1e-9));
        CHECK(inside == radiant::test::relativeTo(0.09, 1e-3));
        CHECK(eulerCharacteristic(mesh, 0) == 1);
        CHECK(countTJunctions(mesh, 0, 0.05) == 0);
        for (const Patch& patch : mesh.patches) CHECK(patch.area <= 0.005 * (1 + 1e-5));
    }
}

TEST_CASE("every patch lies in the element-tree root that holds its centroid: both split a cut face alike") {
    // The floor's cut pieces have up to six corners here, and an octagon stands for a glTF n-gon. A
    // patch across two roots would read only the one holding its centroid (ElementTree::locate).
    std::vector<glm::dvec3> octagon;
    for (int k = 0; k < 8; ++k) {
        const double a = 2 * std::numbers::pi * k / 8;
        octagon.push_back({3 + std::cos(a), 3 + std::sin(a), 0});
    }
    for (const bool triangles : {false, true}) {
        CAPTURE(triangles);
        const Scene scene = grey({{"floor", 0, floorFaces(triangles), "test"}, {"box", 0, boxFaces(), "test"},
                                  {"octagon", 0, {makeFace(octagon)}, "test"}},
                                 0);
        const PatchMesh mesh = meshScene(scene, {0.005});
        const ElementTree tree(scene);
        std::size_t fiveOrMore = 0;
        for (const ElementIndex root : tree.roots()) fiveOrMore += tree.polygon(root).count > 4;
        CHECK(fiveOrMore == 0);
        std::size_t outside = 0;
        for (const Patch& patch : mesh.patches) {
            const ElementIndex root = tree.locate(patch.surface, patch.face, patch.centroid, 1e300);
            REQUIRE(root != kNoElement);
            for (std::size_t c = 0; c < patch.cornerCount; ++c)
                if (!tree.contains(root, mesh.vertices[patch.corners[c]])) ++outside;
        }
        CHECK(outside == 0);
    }
}

TEST_CASE("a 2 cm box on a 100 m floor still cuts it: a contact snaps at a share of its own length") {
    // The scene's diagonal is ~141 m, whose snap distance (7 cm) is larger than the box.
    const double side = 0.02, height = 0.02;
    std::vector<Face> box;
    const std::array<glm::dvec3, 4> f{glm::dvec3{50, 50, 0}, {50 + side, 50, 0}, {50 + side, 50 + side, 0}, {50, 50 + side, 0}};
    const glm::dvec3 up(0, 0, height);
    for (std::size_t i = 0; i < 4; ++i) box.push_back(makeFace({f[i], f[(i + 1) % 4], f[(i + 1) % 4] + up, f[i] + up}));
    const Scene scene = grey({{"floor", 0, {makeFace({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}})}, "test"},
                              {"box", 0, box, "test"}},
                             0);
    const detail::ContactPolygons cut = detail::cutAlongContacts(scene);
    REQUIRE(cut[0].size() == 1);
    double footprint = 0;
    for (const auto& piece : cut[0][0]) {
        Face face;
        face.vertices = piece;
        face.updateGeometry();
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& c : piece) centre += c / static_cast<double>(piece.size());
        if (centre.x > 50 && centre.x < 50 + side && centre.y > 50 && centre.y < 50 + side) footprint += face.area;
    }
    CHECK(footprint == radiant::test::relativeTo(side * side, 1e-6));
}

TEST_CASE("a floor too crowded to cut is meshed uncut, and the load says so") {
    // 60 boxes turned by different angles: 240 lines across the floor would make ~29,000 pieces.
    std::vector<Face> boxes;
    for (int k = 0; k < 60; ++k) {
        const double turn = 0.37 * k, half = 0.1;
        const glm::dvec3 centre(1 + (k % 10) * 1.5, 1 + (k / 10) * 1.5, 0);
        const glm::dvec3 u(std::cos(turn), std::sin(turn), 0), v(-std::sin(turn), std::cos(turn), 0), up(0, 0, 0.5);
        const std::array<glm::dvec3, 4> f{centre - half * u - half * v, centre + half * u - half * v,
                                          centre + half * u + half * v, centre - half * u + half * v};
        for (std::size_t i = 0; i < 4; ++i) boxes.push_back(makeFace({f[i], f[(i + 1) % 4], f[(i + 1) % 4] + up, f[i] + up}));
    }
    Scene scene = grey({{"floor", 0, {makeFace({{0, 0, 0}, {16, 0, 0}, {16, 10, 0}, {0, 10, 0}})}, "test"},
                        {"boxes", 0, boxes, "test"}},
                       0);
    std::vector<std::string> warnings;
    const detail::ContactPolygons cut = detail::cutAlongContacts(scene, &warnings);
    CHECK(cut[0][0].empty());  // uncut
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("surface 'floor': the 240 edges standing on it would cut it into more than 4096 pieces") !=
          std::string::npos);
    const PatchMesh mesh = meshScene(scene, {0.5});
    double floorArea = 0;
    for (std::size_t p = mesh.surfaceFirstPatch[0]; p < mesh.surfaceFirstPatch[1]; ++p) floorArea += mesh.patches[p].area;
    CHECK(floorArea == radiant::test::relativeTo(160.0, 1e-9));
}

TEST_CASE("a box's own top and a twin coplanar face cut nothing: a floor with nothing on it is one grid") {
    // Edges lying in the floor's plane but of a face parallel to it (a lid resting face down, a
    // double-sided twin) and edges of faces below the floor are no contacts.
    const auto f = footprint();
    Face lid = makeFace({f[3], f[2], f[1], f[0]});  // facing down onto the floor
    std::vector<Face> below;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 a = f[i], b = f[(i + 1) % 4], down(0, 0, -0.3);
        below.push_back(makeFace({b, a, a + down, b + down}));
    }
    const Scene scene = grey({{"floor", 0, floorFaces(false), "test"}, {"lid", 0, {lid}, "test"}, {"below", 0, below, "test"}}, 0);
    const PatchMesh mesh = meshScene(scene, {0.01 * (1 + 1e-6)});
    CHECK(mesh.surfaceFirstPatch[1] - mesh.surfaceFirstPatch[0] == 100);
}

namespace {
/// A unit room facing in (grey, E = 1, rho = 0.5) with the box of boxFaces standing on its floor,
/// or sunk `sunk` metres into it.
Scene furnaceWithBox(double sunk) {
    std::vector<Face> ceiling{makeFace({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}})};
    std::vector<Face> walls{makeFace({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}), makeFace({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}),
                            makeFace({{1, 1, 0}, {1, 1, 1}, {0, 1, 1}, {0, 1, 0}}), makeFace({{0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {0, 0, 0}})};
    return grey({{"floor", 0, floorFaces(false), "test"}, {"ceiling", 0, ceiling, "test"}, {"walls", 0, walls, "test"},
                 {"box", 0, boxFaces(sunk), "test"}},
                1.0);
}

/// Gauss-Seidel stepped to residual 1e-7 (the closed form's 1% is then the form factors').
std::vector<Rgb> convergedGaussSeidel(const Scene& scene, const PatchMesh& mesh) {
    SolverOptions options;
    options.rays = std::make_shared<const RayCaster>(scene);
    auto solver = makeSolver(SolverMethod::GaussSeidel, scene, mesh, options);
    for (std::size_t k = 0; k < 500 && solver->lastStats().residual > 1e-7; ++k) solver->step();
    REQUIRE(solver->lastStats().residual <= 1e-7);
    return solver->solution();
}
} // namespace

TEST_CASE("closed furnace with a box standing on the floor or sunk into it: every open patch at E / (1 - rho), the floor along the box too") {
    // A unit room facing in, the box inside facing out; E = 1, rho = 0.5 everywhere, so the closed
    // form is B = 2 on every patch that sees only the enclosure (the floor under the box sees the
    // box's backs and is left out). Sunk 2 cm, the box cuts the floor and the floor cuts its sides
    // where they cross: uncut, the floor beside it was 10% and the sides 13% low.
    for (const double sunk : {0.0, 0.02}) {
    CAPTURE(sunk);
    const Scene scene = furnaceWithBox(sunk);
    const PatchMesh mesh = meshScene(scene, {0.01});
    const std::vector<Rgb> b = convergedGaussSeidel(scene, mesh);
    double worstFloor = 0, worst = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Patch& patch = mesh.patches[i];
        // Nothing reaches a covered patch: B = E exactly (rays grazing the footprint's line leaked
        // light into such patches before they were left out of the form factors).
        if (patch.covered) CHECK(b[i].x == doctest::Approx(1.0).epsilon(1e-12).scale(0));
        if (patch.surface == 0 && insideFootprint(patch.centroid) > 0) continue;
        // A sunk box's sides below the floor face the void under it, out of the room: B = E there.
        if (patch.centroid.z < 0) continue;
        const double error = std::abs(b[i].x / 2.0 - 1);
        worst = std::max(worst, error);
        if (patch.surface == 0 && insideFootprint(patch.centroid) > -0.1) worstFloor = std::max(worstFloor, error);
    }
    CAPTURE(worstFloor);
    // Form factors sum to 1 per row to quadrature accuracy (test_comparison.cpp: the furnace within 1%).
    CHECK(worst < 0.01);
    CHECK(worstFloor < 0.01);
    }
}

TEST_CASE("hierarchical radiosity in the closed furnace with a box on the floor: the covered patches at B = E, the open ones at E / (1 - rho)") {
    // No light reaches the floor under the box (it sees only the box's backs): B = E = 1 there
    // exactly, whatever the solver, and the open patches at the closed form 2. The hierarchical
    // solver skips the covered patches' rows on Patch::covered rather than cast their rays.
    // Uniform patches: with the finer ones the mesher lays along the box's foot (besideContactAreaShare
    // 0.5) the worst open patch, a floor patch at the foot, reads 2.0-2.6% over seeds 1-6 (1.6-2.3%
    // uniform): the patch rows read the visible share of a link whose receiver is up to kLargeReceiver
    // times the patch, which at the foot is not the small patch's own. Open in issue 14
    // (docs/ARCHITECTURE.md, "Accuracy", item 23).
    const Scene scene = furnaceWithBox(0);
    MeshingOptions meshing{0.01};
    meshing.besideContactAreaShare = 1;
    const PatchMesh mesh = meshScene(scene, meshing);
    SolverOptions options;
    options.rays = std::make_shared<const RayCaster>(scene);
    auto solver = makeSolver(SolverMethod::Hierarchical, scene, mesh, options);
    for (std::size_t k = 0; k < 200 && solver->lastStats().residual > 1e-7; ++k) solver->step();
    REQUIRE(solver->lastStats().residual <= 1e-7);
    const std::vector<Rgb> b = solver->solution();
    std::size_t covered = 0;
    double worstOpen = 0, squares = 0, area = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Patch& patch = mesh.patches[i];
        if (patch.covered) {
            ++covered;
            CHECK(b[i].x == doctest::Approx(1.0).epsilon(1e-9).scale(0));
            continue;
        }
        const double error = b[i].x / 2.0 - 1;
        worstOpen = std::max(worstOpen, std::abs(error));
        squares += patch.area * error * error;
        area += patch.area;
    }
    CHECK(covered > 0);
    const double rms = std::sqrt(squares / area);
    CAPTURE(rms);
    CAPTURE(worstOpen);
    CHECK(rms < 0.005);
    CHECK(worstOpen < 0.02);
}

TEST_CASE("closed furnace with a box on the floor: the radiosity drawn beside the box's foot and up its sides is E / (1 - rho), the covered patches left out") {
    // The scene of the test above. The floor under the box and a sunk box's sides below the floor see
    // only backs (B = 0 and B = E = 1): averaged into the vertices of the foot they drew the floor
    // 0.5 cm from the box at 1.50 against 2. Every value drawn or interpolated on an open patch must
    // be the closed form B = E / (1 - rho) = 2, within the 1% the patches themselves are.
    for (const double sunk : {0.0, 0.02}) {
        CAPTURE(sunk);
        const Scene scene = furnaceWithBox(sunk);
        const PatchMesh mesh = meshScene(scene, {0.01});
        // The geometry first: covered exactly under the box and below the floor.
        for (std::size_t i = 0; i < mesh.size(); ++i) {
            const Patch& patch = mesh.patches[i];
            CAPTURE(i);
            if (patch.surface == 0) CHECK(patch.covered == (insideFootprint(patch.centroid) > 0));
            else if (patch.surface == 3) CHECK(patch.covered == (patch.centroid.z < 0));
            else CHECK_FALSE(patch.covered);
        }
        const std::vector<Rgb> b = convergedGaussSeidel(scene, mesh);

        // Points 0.5, 1 and 2 cm out from each side on the floor and up each side, at a tenth, the
        // middle and nine tenths of the side.
        const auto f = footprint();
        const PatchLocator locator(mesh);
        const auto worstInterpolated = [&](const PatchMesh& m, double& lowest) {
            double worst = 0;
            lowest = 1e9;
            for (std::size_t side = 0; side < 4; ++side) {
                const glm::dvec3 along = f[(side + 1) % 4] - f[side];
                const glm::dvec3 out = glm::normalize(glm::cross(along, glm::dvec3(0, 0, 1)));
                for (const double t : {0.1, 0.5, 0.9})
                    for (const double d : {0.005, 0.01, 0.02}) {
                        const glm::dvec3 foot = f[side] + t * along;
                        const glm::dvec3 onFloor = foot + d * out, onSide = foot + glm::dvec3(0, 0, d);
                        for (const auto& [surface, face, point] :
                             {std::tuple<std::uint32_t, std::uint32_t, glm::dvec3>{0, 0, onFloor},
                              std::tuple<std::uint32_t, std::uint32_t, glm::dvec3>{3, static_cast<std::uint32_t>(side), onSide}}) {
                            const std::size_t patch = locator.find(surface, face, point);
                            REQUIRE(patch != PatchLocator::npos);
                            const double drawn = interpolateRadiosity(m, b, patch, point).x;
                            const double fromVertices = interpolateRadiosity(m, patch, point, vertexRadiosity(m, b)).x;
                            lowest = std::min({lowest, drawn, fromVertices});
                            worst = std::max({worst, std::abs(drawn / 2 - 1), std::abs(fromVertices / 2 - 1)});
                        }
                    }
            }
            return worst;
        };
        PatchMesh asBefore = mesh;  // every patch taken as open: the averages drawn before the fix
        for (Patch& patch : asBefore.patches) patch.covered = false;
        double lowestBefore = 0, lowest = 0;
        const double before = worstInterpolated(asBefore, lowestBefore);
        const double after = worstInterpolated(mesh, lowest);
        MESSAGE("sunk " << sunk << " m: interpolated beside the foot, worst |B/2 - 1| " << before << " (lowest "
                        << lowestBefore << ") with covered patches averaged in, " << after << " (lowest " << lowest
                        << ") without");
        CHECK(after < 0.01);

        // Every vertex value an open patch is drawn with, by the probe's nodal averages and by the
        // 3D view's smoothing groups.
        const std::vector<Rgb> nodal = vertexRadiosity(mesh, b);
        const render::SmoothingGroups groups = render::findSmoothingGroups(mesh);
        std::vector<double> areas;
        for (const Patch& patch : mesh.patches) areas.push_back(patch.area);
        std::vector<Rgb> smooth;
        render::smoothRadiosity(groups, areas, b, smooth);
        double worstNodal = 0, worstSmooth = 0;
        for (std::size_t i = 0; i < mesh.size(); ++i) {
            if (mesh.patches[i].covered) continue;
            for (std::size_t c = 0; c < mesh.patches[i].cornerCount; ++c) {
                worstNodal = std::max(worstNodal, std::abs(nodal[mesh.patches[i].corners[c]].x / 2 - 1));
                worstSmooth = std::max(worstSmooth, std::abs(smooth[groups.cornerVertex[i][c]].x / 2 - 1));
            }
        }
        CAPTURE(worstNodal);
        CAPTURE(worstSmooth);
        CHECK(worstNodal < 0.01);
        CHECK(worstSmooth < 0.01);
    }
}

}

TEST_SUITE("scenes") {

TEST_CASE("the floor along a block's foot is meshed finer (besideContactAreaShare), the footprint and a bare floor not") {
    // A block square to the floor's edges, [0.3, 0.6] x [0.4, 0.7], 0.2 m high: the pieces of floor
    // along its four sides ask for half the area, and conformity carries their finer counts along
    // their rows and columns; a floor with nothing on it is meshed as before.
    const auto blockOn = [](double x0, double x1, double y0, double y1) {
        const glm::dvec3 up(0, 0, 0.2);
        const std::array<glm::dvec3, 4> f{glm::dvec3(x0, y0, 0), glm::dvec3(x1, y0, 0), glm::dvec3(x1, y1, 0), glm::dvec3(x0, y1, 0)};
        std::vector<Face> faces;
        for (std::size_t i = 0; i < 4; ++i) faces.push_back(makeFace({f[i], f[(i + 1) % 4], f[(i + 1) % 4] + up, f[i] + up}));
        faces.push_back(makeFace({f[0] + up, f[1] + up, f[2] + up, f[3] + up}));
        return faces;
    };
    const Scene scene = grey({{"floor", 0, floorFaces(false), "test"}, {"block", 0, blockOn(0.3, 0.6, 0.4, 0.7), "test"}}, 0);
    const double maxArea = 0.005;
    MeshingOptions uniform{maxArea};
    uniform.besideContactAreaShare = 1;
    const MeshingOptions finer{maxArea};
    REQUIRE(finer.besideContactAreaShare == 0.5);
    const PatchMesh before = meshScene(scene, uniform);
    const PatchMesh mesh = meshScene(scene, finer);
    CHECK(mesh.size() > before.size());
    CHECK(estimatePatchCount(scene, finer) == mesh.size());
    std::size_t along = 0, footprint = 0;
    for (std::size_t p = mesh.surfaceFirstPatch[0]; p < mesh.surfaceFirstPatch[1]; ++p) {
        const Patch& patch = mesh.patches[p];
        CHECK(patch.area <= maxArea * (1 + 1e-5));
        const glm::dvec3 c = patch.centroid;
        const bool under = c.x > 0.3 && c.x < 0.6 && c.y > 0.4 && c.y < 0.7;
        // Beside a side: within 5 cm of it, outside the footprint, along its length.
        const bool beside = !under && ((c.x > 0.3 && c.x < 0.6 && (std::abs(c.y - 0.4) < 0.05 || std::abs(c.y - 0.7) < 0.05)) ||
                                       (c.y > 0.4 && c.y < 0.7 && (std::abs(c.x - 0.3) < 0.05 || std::abs(c.x - 0.6) < 0.05)));
        if (beside) {
            ++along;
            CHECK(patch.area <= 0.5 * maxArea * (1 + 1e-5));
        }
        if (under) {
            ++footprint;
            CHECK(patch.covered);
        }
    }
    CHECK(along > 0);
    CHECK(footprint > 0);
    CHECK(countTJunctions(mesh, 0, 0.05) == 0);
    CHECK(eulerCharacteristic(mesh, 0) == 1);

    // A bare floor: the same mesh whatever the share.
    const Scene bare = grey({{"floor", 0, floorFaces(false), "test"}}, 0);
    CHECK(meshScene(bare, finer).size() == meshScene(bare, uniform).size());

    // A share outside (0, 1] is refused, named.
    for (const double share : {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
        MeshingOptions bad{maxArea};
        bad.besideContactAreaShare = share;
        CHECK_THROWS_WITH_AS(meshScene(scene, bad), doctest::Contains("patch area beside contacts"), RadiantError);
    }
}

}

TEST_CASE("the element tree built from the mesh's contact cuts has the roots it cuts itself") {
    // The hierarchical solver hands its tree the cuts the mesher made (PatchMesh::contactCuts)
    // instead of cutting the scene again; the roots must be the same polygons, and cuts that do not
    // fit the scene are ignored.
    const Scene scene = makeCornellBox();
    const PatchMesh mesh = meshScene(scene, {0.01});
    REQUIRE(mesh.contactCuts != nullptr);
    const ElementTree cut(scene), given(scene, mesh.contactCuts.get());
    const auto sameRoots = [&](const ElementTree& tree) {
        if (tree.roots().size() != cut.roots().size()) return false;
        for (std::size_t i = 0; i < cut.roots().size(); ++i) {
            const PatchPolygon& a = cut.polygon(cut.roots()[i]);
            const PatchPolygon& b = tree.polygon(tree.roots()[i]);
            if (a.count != b.count || tree.surface(tree.roots()[i]) != cut.surface(cut.roots()[i])) return false;
            for (std::size_t c = 0; c < a.count; ++c)
                if (a.vertices[c] != b.vertices[c]) return false;
        }
        return true;
    };
    CHECK(cut.roots().size() > scene.faceCount());  // the floor is cut round both blocks
    CHECK(sameRoots(given));
    const detail::ContactPolygons wrong(scene.surfaces.size() + 1);
    CHECK(sameRoots(ElementTree(scene, &wrong)));
}
