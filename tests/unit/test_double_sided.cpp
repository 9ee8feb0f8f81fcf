// Double-sided faces (glTF doubleSided, Blender's default; issue #20): each face is two surfaces back
// to back that never exchange light with each other. Their corners are one float-rounded set,
// reversed, so the twins lie in each other's plane only to the faces' planarity: a tolerance far
// below that once let each twin cover the other's whole hemisphere (F = 0.42 on average over a
// sphere's facets), lighting a closed sphere's inside and brightening its outside by 14%.
// Closed forms (/work/shared/reference/oracles.md, docs/reference.md):
//  - no light enters a closed surface: the inside of a closed sphere or box has E = 0, so B = M;
//  - a closed enclosure whose every surface emits M and reflects rho (the furnace): B = M / (1 - rho)
//    everywhere inside; a closed box's outside in the void sees nothing, so B = M there;
//  - a closed enclosure of uniform rho: (1 - rho) sum A B = sum A M;
//  - the same geometry under the same light: a double-sided sphere's outside reads as the
//    single-sided sphere's.
// Tolerances are relative (.scale(0)). "Black" is B below 2e-4 of the outside's: a visibility ray
// leaving a facet within a float's precision of its edge (~5e-7 m) may miss the neighbour it crosses
// there (the ray caster takes points that close to a plane as on it), 1 in ~10^5 of them. The
// progressive and hierarchical bounds are looser: a pair none of whose rays joins parts in front of
// each other falls back to the plain fraction of rays that got through (ProgressiveShot.cpp,
// HierarchicalFormFactor.h), and such rays from a facet's back leave the sphere through it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/Solver.h"

using namespace radiant;

namespace {

constexpr SolverMethod kEveryMethod[] = {SolverMethod::Jacobi, SolverMethod::GaussSeidel, SolverMethod::Progressive,
                                         SolverMethod::Hierarchical, SolverMethod::Importance};

/// A point as a glTF file stores it (float), turned by a fixed rotation first so that no coordinate
/// is exact: the float rounding then tilts each face's corners off one plane, as in Blender's exports.
glm::dvec3 asStored(glm::dvec3 p) {
    const double a = 0.37, b = 0.91;
    p = {std::cos(a) * p.x - std::sin(a) * p.z, p.y, std::sin(a) * p.x + std::cos(a) * p.z};
    p = {p.x, std::cos(b) * p.y - std::sin(b) * p.z, std::sin(b) * p.y + std::cos(b) * p.z};
    return glm::dvec3(glm::vec3(p));
}

Face face(std::vector<glm::dvec3> corners) {
    Face f;
    for (const glm::dvec3& c : corners) f.vertices.push_back(asStored(c));
    f.updateGeometry();
    return f;
}

/// The six faces of the cube [-h, h]^3 (+ centre), facing outward (Blender's cube).
std::vector<Face> cubeOutward(glm::dvec3 centre, double h) {
    const auto p = [&](double x, double y, double z) { return centre + h * glm::dvec3(x, y, z); };
    return {face({p(-1, -1, -1), p(1, -1, -1), p(1, -1, 1), p(-1, -1, 1)}), face({p(-1, 1, -1), p(-1, 1, 1), p(1, 1, 1), p(1, 1, -1)}),
            face({p(-1, -1, -1), p(-1, -1, 1), p(-1, 1, 1), p(-1, 1, -1)}), face({p(1, -1, -1), p(1, 1, -1), p(1, 1, 1), p(1, -1, 1)}),
            face({p(-1, -1, -1), p(-1, 1, -1), p(1, 1, -1), p(1, -1, -1)}), face({p(-1, -1, 1), p(1, -1, 1), p(1, 1, 1), p(-1, 1, 1)})};
}

/// A UV sphere (`segments` x `rings`), faces counter-clockwise seen from outside.
std::vector<Face> uvSphere(glm::dvec3 centre, double radius, int segments, int rings) {
    const auto at = [&](int ring, int segment) {
        const double polar = std::numbers::pi * ring / rings, azimuth = 2 * std::numbers::pi * segment / segments;
        return centre + radius * glm::dvec3(std::sin(polar) * std::cos(azimuth), std::cos(polar), -std::sin(polar) * std::sin(azimuth));
    };
    std::vector<Face> faces;
    for (int ring = 0; ring < rings; ++ring)
        for (int s = 0; s < segments; ++s) {
            if (ring == 0)
                faces.push_back(face({at(0, 0), at(1, s), at(1, s + 1)}));
            else if (ring == rings - 1)
                faces.push_back(face({at(rings, 0), at(rings - 1, s + 1), at(rings - 1, s)}));
            else
                faces.push_back(face({at(ring, s), at(ring + 1, s), at(ring + 1, s + 1), at(ring, s + 1)}));
        }
    return faces;
}

/// Appends `faces` as a double-sided surface, as the glTF loader makes one: the front as given, then
/// "<name> (back)" with each face's corners reversed, still fanning from the first.
void addDoubleSided(Scene& scene, const std::string& name, std::size_t material, std::vector<Face> faces) {
    Surface front{name, material, faces, "test"};
    front.side = FaceSide::Front;
    for (Face& f : faces) {
        std::reverse(f.vertices.begin() + 1, f.vertices.end());
        f.updateGeometry();
    }
    Surface back{name + " (back)", material, std::move(faces), "test"};
    back.side = FaceSide::Back;
    scene.surfaces.push_back(std::move(front));
    scene.surfaces.push_back(std::move(back));
}

std::vector<Rgb> solveWith(SolverMethod method, const Scene& scene, const PatchMesh& mesh, double tolerance) {
    const auto solver = makeSolver(method, scene, mesh);
    for (int k = 0; k < 100000 && solver->lastStats().residual > tolerance; ++k) solver->step();
    CHECK(solver->lastStats().residual <= tolerance);
    return solver->solution();
}

struct SurfaceRange {
    double meanB = 0, minB = 0, maxB = 0, area = 0;
};

SurfaceRange range(const Scene& scene, const PatchMesh& mesh, const std::vector<Rgb>& b, const std::string& name) {
    const std::size_t s = scene.findSurface(name);
    REQUIRE(s != Scene::npos);
    SurfaceRange r{0, 1e300, -1e300, 0};
    double power = 0;
    for (std::size_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
        r.area += mesh.patches[i].area;
        power += mesh.patches[i].area * b[i].x;
        r.minB = std::min(r.minB, b[i].x);
        r.maxB = std::max(r.maxB, b[i].x);
    }
    r.meanB = power / r.area;
    return r;
}

std::string sphereRoom(bool doubleSided) {
    return std::string(RADIANT_TEST_DATA_DIR) + (doubleSided ? "/curved/sphere_room_double_sided.gltf" : "/curved/sphere_room.gltf");
}

} // namespace

TEST_SUITE("double-sided") {

TEST_CASE("a double-sided face's twins lie in one plane and exchange nothing, from float-stored corners") {
    // Every facet of the glTF sphere against its own twin: coplanar, so F = 0 both ways (it was 0.42
    // on average), and the pair is culled before any ray.
    const Scene scene = loadScene(sphereRoom(true)).scene;
    const PatchMesh mesh = meshScene(scene, MeshingOptions{0.02});
    const std::size_t front = scene.findSurface("sphere"), back = scene.findSurface("sphere (back)");
    REQUIRE(back == front + 1);
    const std::size_t count = mesh.surfaceFirstPatch[front + 1] - mesh.surfaceFirstPatch[front];
    REQUIRE(count == mesh.surfaceFirstPatch[back + 1] - mesh.surfaceFirstPatch[back]);
    REQUIRE(count >= 512);
    std::size_t exchanging = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const PatchPolygon outside = mesh.polygon(mesh.surfaceFirstPatch[front] + k);
        const PatchPolygon inside = mesh.polygon(mesh.surfaceFirstPatch[back] + k);
        REQUIRE(glm::dot(outside.normal, inside.normal) < -0.999999);
        if (unoccludedFormFactor(outside, inside) != 0 || unoccludedFormFactor(inside, outside) != 0 ||
            !cannotSeeEachOther(outside, inside))
            ++exchanging;
    }
    CHECK(exchanging == 0);
}

// ctest-case-labels: heavy
TEST_CASE("the inside of a closed double-sided sphere stays dark in every method") {
    // A float-stored 16 x 8 double-sided UV sphere (emitting nothing) in a glowing closed box, all of
    // reflectance rho = 0.5: nothing reaches the sphere's inside (E = 0, so B = 0 at every inner
    // patch), and the enclosure around it, the box's inside and the sphere's outside, absorbs all the
    // box emits: (1 - rho) sum A B = sum A M. Light lost into the cavity would break the balance.
    Scene scene;
    scene.name = "double-sided sphere in a glowing box";
    scene.materials = {{"glowing", Rgb(0.5), ExitanceRgb(Rgb(1.0))}, {"sphere", Rgb(0.5), ExitanceRgb(Rgb(0.0))}};
    std::vector<Face> box = cubeOutward({0, 0, 0}, 1);
    for (Face& f : box) {  // facing inward
        std::reverse(f.vertices.begin() + 1, f.vertices.end());
        f.updateGeometry();
    }
    scene.surfaces.push_back({"box", 0, std::move(box), "test"});
    addDoubleSided(scene, "sphere", 1, uvSphere({0.05, -0.1, 0.02}, 0.5, 16, 8));
    const PatchMesh mesh = meshScene(scene, MeshingOptions{0.05});
    for (const SolverMethod method : kEveryMethod) {
        CAPTURE(methodName(method));
        const std::vector<Rgb> b = solveWith(method, scene, mesh, 1e-7);
        const SurfaceRange inside = range(scene, mesh, b, "sphere (back)");
        const SurfaceRange outside = range(scene, mesh, b, "sphere");
        const SurfaceRange walls = range(scene, mesh, b, "box");
        MESSAGE(methodName(method) << ": sphere inside " << inside.meanB << " (max " << inside.maxB << "), outside "
                                   << outside.meanB << ", box " << walls.meanB);
        const bool matrix = method == SolverMethod::Jacobi || method == SolverMethod::GaussSeidel;
        CHECK(inside.maxB <= (matrix ? 2e-4 : 1e-2) * outside.meanB);
        CHECK(inside.meanB <= (matrix ? 2e-5 : 2e-3) * outside.meanB);
        const double absorbed = (1 - 0.5) * (walls.meanB * walls.area + outside.meanB * outside.area);
        CHECK(absorbed == doctest::Approx(1.0 * walls.area).scale(0).epsilon(0.005));
    }
}

TEST_CASE("a closed double-sided box in the void: B = M / (1 - rho) inside, B = M outside, in every method") {
    // Blender's cube as a closed glowing box (every face emits M = 1 from both sides, rho = 0.5):
    // inside, the furnace; outside, each face sees nothing and only emits. Energy balance: what the
    // outside emits leaves; the inside absorbs all it emits, (1 - rho) sum A B = sum A M.
    Scene scene;
    scene.name = "double-sided furnace box";
    scene.materials = {{"glowing", Rgb(0.5), ExitanceRgb(Rgb(1.0))}};
    addDoubleSided(scene, "Cube", 0, cubeOutward({0.1, 0.2, -0.3}, 1));
    const PatchMesh mesh = meshScene(scene, MeshingOptions{0.1});
    for (const SolverMethod method : kEveryMethod) {
        CAPTURE(methodName(method));
        const std::vector<Rgb> b = solveWith(method, scene, mesh, 1e-7);
        const SurfaceRange inside = range(scene, mesh, b, "Cube (back)");
        const SurfaceRange outside = range(scene, mesh, b, "Cube");
        MESSAGE(methodName(method) << ": inside " << inside.minB << " .. " << inside.maxB << ", outside " << outside.minB
                                   << " .. " << outside.maxB);
        CHECK(outside.minB == doctest::Approx(1.0).scale(0).epsilon(1e-9));
        CHECK(outside.maxB == doctest::Approx(1.0).scale(0).epsilon(1e-9));
        CHECK(inside.minB == doctest::Approx(2.0).scale(0).epsilon(0.01));
        CHECK(inside.maxB == doctest::Approx(2.0).scale(0).epsilon(0.01));
        CHECK((1 - 0.5) * inside.meanB * inside.area == doctest::Approx(1.0 * inside.area).scale(0).epsilon(0.005));
    }
}

TEST_CASE("the double-sided sphere room lights the sphere's outside as the single-sided one, and not its inside") {
    // tests/data/curved: the same 32 x 16 UV sphere in the same closed lit room, once single-sided and
    // once "doubleSided": true. Its twin adds surfaces only inside the closed sphere, where no light
    // goes, so every surface of the room and the sphere's outside read the same (Gauss-Seidel on the
    // same mesh; the double-sided one was 14% brighter), and so does the probe at its equator.
    const Scene single = loadScene(sphereRoom(false)).scene;
    const Scene twoSided = loadScene(sphereRoom(true)).scene;
    const PatchMesh singleMesh = meshScene(single, MeshingOptions{0.05});
    const PatchMesh twoSidedMesh = meshScene(twoSided, MeshingOptions{0.05});
    const std::vector<Rgb> singleB = solveWith(SolverMethod::GaussSeidel, single, singleMesh, 1e-8);
    const std::vector<Rgb> twoSidedB = solveWith(SolverMethod::GaussSeidel, twoSided, twoSidedMesh, 1e-8);
    for (const Surface& surface : single.surfaces) {
        CAPTURE(surface.name);
        const double a = range(single, singleMesh, singleB, surface.name).meanB;
        const double b = range(twoSided, twoSidedMesh, twoSidedB, surface.name).meanB;
        MESSAGE(surface.name << ": single-sided " << a << ", double-sided " << b);
        CHECK(b == doctest::Approx(a).scale(0).epsilon(1e-4));
    }
    CHECK(range(twoSided, twoSidedMesh, twoSidedB, "sphere (back)").maxB <= 2e-4 * range(single, singleMesh, singleB, "sphere").meanB);

    // The probe's final gather at the equator (a facet's centre, facing out) and inside it.
    const glm::dvec3 point(0.490438791, 0.748772581, -0.0483040048), normal(0.990438351, 0.0975496631, -0.0975496631);
    const RayCaster singleRays(single), twoSidedRays(twoSided);
    const Probe singleProbe(single, singleMesh, &singleRays), twoSidedProbe(twoSided, twoSidedMesh, &twoSidedRays);
    const double e1 = singleProbe.measure(point, normal, singleB).irradiance.value().x;
    const double e2 = twoSidedProbe.measure(point, normal, twoSidedB).irradiance.value().x;
    CHECK(e2 == doctest::Approx(e1).scale(0).epsilon(1e-4));
    const ProbeReading within = twoSidedProbe.measure(point, -normal, twoSidedB);
    CHECK(twoSided.surfaces[within.at.surface].name == "sphere (back)");
    CHECK(within.irradiance.value().x <= 1e-5 * e1);
}

} // TEST_SUITE
