// ctest-labels: threads
// Hierarchical and importance-driven radiosity against closed forms (docs/reference.md): the
// furnace, two parallel plates, energy balance in a closed box, the adjoint identity. Expected
// values are computed here from the formulas, never taken from the solver.
#include <doctest/doctest.h>

#include "tests/support/CatalogViewFactors.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/HierarchicalSolver.h"
#include "radiometry/solver/ImportanceSolver.h"
#include "radiometry/solver/Solver.h"
#include "tests/support/MeshTopology.h"

using namespace radiant;

namespace {

using radiant::test::makeFace;

/// Turns the face around when its normal does not point towards `inside`.
Face facing(Face face, const glm::dvec3& inside) {
    glm::dvec3 centre(0.0);
    for (const auto& v : face.vertices) centre += v / static_cast<double>(face.vertices.size());
    if (glm::dot(face.normal, inside - centre) < 0) {
        std::reverse(face.vertices.begin(), face.vertices.end());
        face.updateGeometry();
    }
    return face;
}

/// A closed box [0,w]x[0,h]x[0,d], faces inward, one surface per face; material m per face.
Scene makeClosedBox(glm::dvec3 size, const std::vector<Material>& materials, const std::array<std::size_t, 6>& faceMaterial) {
    Scene scene;
    scene.name = "test box";
    scene.materials = materials;
    const glm::dvec3 c = 0.5 * size;
    const double w = size.x, h = size.y, d = size.z;
    const Face faces[6] = {
        facing(makeFace({{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}}), c),  // floor
        facing(makeFace({{0, h, 0}, {w, h, 0}, {w, h, d}, {0, h, d}}), c),  // ceiling
        facing(makeFace({{0, 0, 0}, {0, h, 0}, {0, h, d}, {0, 0, d}}), c),  // x = 0
        facing(makeFace({{w, 0, 0}, {w, h, 0}, {w, h, d}, {w, 0, d}}), c),  // x = w
        facing(makeFace({{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}}), c),  // z = 0
        facing(makeFace({{0, 0, d}, {w, 0, d}, {w, h, d}, {0, h, d}}), c),  // z = d
    };
    for (int i = 0; i < 6; ++i)
        scene.surfaces.push_back({"face " + std::to_string(i), faceMaterial[static_cast<std::size_t>(i)], {faces[i]}, "test"});
    return scene;
}

/// Two directly opposed a x b rectangles c apart, facing each other.
Scene makePlates(double a, double b, double c, const Material& lower, const Material& upper) {
    Scene scene;
    scene.name = "test plates";
    scene.materials = {lower, upper};
    scene.surfaces.push_back({"lower", 0, {makeFace({{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}})}, "test"});
    scene.surfaces.push_back({"upper", 1, {makeFace({{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}})}, "test"});
    return scene;
}

/// One patch per face: the tests compare whole-surface means, independent of the mesher.
PatchMesh facesAsPatches(const Scene& scene) {
    PatchMesh mesh;
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
        for (std::uint32_t f = 0; f < scene.surfaces[s].faces.size(); ++f) {
            const Face& face = scene.surfaces[s].faces[f];
            const PatchPolygon polygon = makeElementPolygon(face.vertices);
            Patch patch;
            patch.surface = s;
            patch.face = f;
            patch.centroid = polygon.centroid;
            patch.normal = face.normal;
            patch.area = face.area;
            mesh.patches.push_back(patch);
        }
    }
    mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
    return mesh;
}

/// Each quad face cut into n x n bilinear patches (centroid and area are all the solver reads).
PatchMesh gridPatches(const Scene& scene, int n) {
    PatchMesh mesh;
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
        for (std::uint32_t f = 0; f < scene.surfaces[s].faces.size(); ++f) {
            const auto& v = scene.surfaces[s].faces[f].vertices;
            REQUIRE(v.size() == 4);
            const auto at = [&](double u, double w) {
                return (1 - w) * ((1 - u) * v[0] + u * v[1]) + w * ((1 - u) * v[3] + u * v[2]);
            };
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < n; ++k) {
                    const std::vector<glm::dvec3> corners = {at(double(i) / n, double(k) / n), at(double(i + 1) / n, double(k) / n),
                                                             at(double(i + 1) / n, double(k + 1) / n), at(double(i) / n, double(k + 1) / n)};
                    const PatchPolygon polygon = makeElementPolygon(corners);
                    Patch patch;
                    patch.surface = s;
                    patch.face = f;
                    patch.centroid = polygon.centroid;
                    patch.normal = polygon.normal;
                    patch.area = polygon.area;
                    mesh.patches.push_back(patch);
                }
        }
    }
    mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
    return mesh;
}


/// Steps until the residual falls below `tolerance` (or `maxSteps`); returns the steps taken.
std::size_t solve(Solver& solver, double tolerance = 1e-7, std::size_t maxSteps = 300) {
    for (std::size_t k = 1; k <= maxSteps; ++k)
        if (solver.step().residual < tolerance) return k;
    return maxSteps + 1;
}

SolverOptions unoccluded(double linkEpsilon = 1e-4, double minElementArea = 1e-4) {
    SolverOptions options;
    options.formFactors.visibilityRays = 0;  // convex scenes: nothing can block
    options.linkEpsilon = linkEpsilon;
    options.minElementArea = minElementArea;
    return options;
}

/// Either method over the same scene; the importance camera looks at `target` from `eye`.
std::unique_ptr<HierarchicalSolver> makeMethod(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                               SolverOptions options, glm::dvec3 eye, glm::dvec3 target,
                                               glm::dvec3 up = {0, 1, 0}) {
    options.view = View{eye, target, up, 1.2, 1.0};
    if (method == SolverMethod::Importance) return std::make_unique<ImportanceSolver>(scene, mesh, options, nullptr);
    return std::make_unique<HierarchicalSolver>(scene, mesh, options, nullptr);
}

constexpr SolverMethod kHierarchicalMethods[] = {SolverMethod::Hierarchical, SolverMethod::Importance};

Material greyMaterial(const std::string& name, double rho, double exitance) {
    return {name, Rgb(rho), ExitanceRgb(Rgb(exitance))};
}

} // namespace

TEST_SUITE("hierarchical") {

TEST_CASE("element tree: roots per face, quad and triangle children tile their parent") {
    Scene scene = makeCornellBox();
    // Without the blocks, whose footprints would cut the floor into more roots (ContactCuts.h).
    std::erase_if(scene.surfaces, [](const Surface& s) { return s.name.find("block") != std::string::npos; });
    // A convex pentagon splits into the mesher's pieces (ConvexFan.h): a quad and a triangle.
    scene.surfaces.push_back({"pentagon", 0,
                              {makeFace({{0, 0, 2}, {1, 0, 2}, {1.3, 0.8, 2}, {0.5, 1.3, 2}, {-0.3, 0.8, 2}})}, "test"});
    ElementTree tree(scene);
    CHECK(tree.roots().size() == scene.faceCount() - 1 + 2);
    double rootArea = 0;
    for (const ElementIndex r : tree.roots()) rootArea += tree.area(r);
    CHECK(rootArea == doctest::Approx(scene.totalArea()).epsilon(1e-12).scale(0));

    for (const ElementIndex r : tree.roots()) {
        const ElementIndex first = tree.subdivide(r);
        double childArea = 0;
        for (ElementIndex c = first; c < first + 4; ++c) {
            childArea += tree.area(c);
            CHECK(tree.parent(c) == r);
            CHECK(tree.polygon(c).count == tree.polygon(r).count);
            CHECK(glm::dot(tree.polygon(c).normal, tree.polygon(r).normal) == doctest::Approx(1.0).scale(0));
        }
        CHECK(childArea == doctest::Approx(tree.area(r)).epsilon(1e-12).scale(0));
        CHECK(tree.subdivide(r) == first);  // idempotent
    }
    CHECK(tree.leafCount() == 4 * tree.roots().size());
    CHECK(tree.leaves().size() == tree.leafCount());

    // locate() descends to the leaf containing the point, stopping at the requested size.
    const std::uint32_t floor = static_cast<std::uint32_t>(scene.findSurface("floor"));
    const glm::dvec3 point{0.1, 0, 0.1};
    const ElementIndex leaf = tree.locate(floor, 0, point);
    REQUIRE(leaf != kNoElement);
    CHECK(tree.isLeaf(leaf));
    CHECK(tree.contains(leaf, point));
    CHECK(tree.surface(leaf) == floor);
    CHECK(tree.locate(floor, 0, point, tree.area(leaf) * 2) == tree.parent(leaf));

    // descend() from an element found before the tree grew below it reaches what locate() finds now.
    const ElementIndex before = tree.locate(floor, 0, point, 0.001);
    const ElementIndex first = tree.subdivide(leaf);
    for (ElementIndex c = first; c < first + 4; ++c) tree.subdivide(c);
    CHECK_FALSE(tree.isLeaf(before));
    for (const double minArea : {0.0, 0.001, tree.area(leaf) / 20}) {
        CAPTURE(minArea);
        CHECK(tree.descend(before, point, minArea) == tree.locate(floor, 0, point, minArea));
    }
    CHECK(tree.locate(floor, 0, point) != before);
}

TEST_CASE("element tree: memory grows linearly with the elements") {
    ElementTree tree(makeCornellBox());
    std::vector<std::pair<std::size_t, std::size_t>> sizes;
    for (int level = 0; level < 6; ++level) {
        for (const ElementIndex e : tree.leaves()) tree.subdivide(e);
        sizes.emplace_back(tree.size(), tree.bytes());
    }
    const double first = static_cast<double>(sizes[2].second) / static_cast<double>(sizes[2].first);
    const double last = static_cast<double>(sizes.back().second) / static_cast<double>(sizes.back().first);
    CHECK(last < 2 * first);  // vector growth at most doubles the bytes per element
    CHECK(last < 450);  // 406 B measured (2026-12-02): vectors' spare capacity at this count included
    MESSAGE(sizes.back().first << " elements in " << sizes.back().second << " bytes (" << last << " B/element)");
}

// ctest-case-labels: heavy
TEST_CASE("hierarchical: the furnace converges to E / (1 - rho)") {
    for (const SolverMethod method : kHierarchicalMethods)
        for (const auto& values : {std::pair{0.3, glm::dvec3(2, 0.5, 1)}, std::pair{0.5, glm::dvec3(1, 1, 1)}}) {
            const double rho = values.first;  // not structured bindings: clang 14 cannot CAPTURE those
            const glm::dvec3 size = values.second;
            {
                CAPTURE(methodName(method));
                CAPTURE(rho);
                const Scene scene = makeClosedBox(size, {greyMaterial("all", rho, 1.0)}, {0, 0, 0, 0, 0, 0});
                // The camera sits inside, looking at the far wall.
                auto solver = makeMethod(method, scene, gridPatches(scene, 4), unoccluded(1e-5, 1e-4), 0.5 * size,
                                         {0.5 * size.x, 0.5 * size.y, size.z});
                CHECK(solve(*solver, 1e-6) < 300);
                const double expected = 1.0 / (1 - rho);
                // Over all leaves, area-weighted: the form factors' row sums on average.
                const ElementTree& tree = solver->elements();
                double sum = 0;
                for (const ElementIndex e : tree.leaves()) sum += tree.area(e) * tree.radiosity()[e].x;
                CHECK(sum / scene.totalArea() == doctest::Approx(expected).epsilon(0.005).scale(0));
                // Per patch (what the window shows). A furnace amplifies form-factor errors by
                // rho / (1 - rho); the worst patches touch the box's concave edges.
                double worst = 0;
                for (const Rgb& b : solver->solution()) worst = std::max(worst, std::abs(b.x / expected - 1));
                CHECK(worst < 0.02 * rho / (1 - rho));
                MESSAGE(methodName(method) << ", rho " << rho << ": " << tree.leafCount() << " leaves, mean off by "
                                           << sum / scene.totalArea() / expected - 1 << ", worst patch by " << worst);
            }
        }
}

TEST_CASE("hierarchical: two parallel plates match the two-patch closed form") {
    struct Case {
        double a, b, c;
    };
    for (const Case g : {Case{1, 1, 1}, Case{1, 1.5, 0.5}, Case{2, 1, 1.5}}) {
        const double F = radiant::test::parallelRectangles(g.a, g.b, g.c);  // equal areas: F12 = F21
        SUBCASE("a black emitter: the receiver's mean is exactly E2 + rho2 F E1") {
            const double E1 = 1, E2 = 0.25, rho2 = 0.6;
            const Scene scene = makePlates(g.a, g.b, g.c, greyMaterial("emitter", 0, E1), greyMaterial("receiver", rho2, E2));
            for (const SolverMethod method : kHierarchicalMethods) {
                CAPTURE(methodName(method));
                // The camera between the plates looks at the receiver.
                auto solver = makeMethod(method, scene, facesAsPatches(scene), unoccluded(1e-5, 1e-5),
                                         {0.5 * g.a, 0.5 * g.b, 0.1 * g.c}, {0.5 * g.a, 0.5 * g.b, g.c});
                solve(*solver);
                CHECK(solver->solution()[0].x == doctest::Approx(E1).epsilon(1e-12).scale(0));
                CHECK(solver->solution()[1].x == doctest::Approx(E2 + rho2 * F * E1).epsilon(2e-3).scale(0));
            }
        }
        SUBCASE("both reflecting: B1 = (E1 + rho1 F12 E2) / (1 - rho1 rho2 F12 F21)") {
            const double E1 = 1, E2 = 0.5, rho1 = 0.4, rho2 = 0.5;
            const Scene scene = makePlates(g.a, g.b, g.c, greyMaterial("one", rho1, E1), greyMaterial("two", rho2, E2));
            const double denominator = 1 - rho1 * rho2 * F * F;
            for (const SolverMethod method : kHierarchicalMethods) {
                CAPTURE(methodName(method));
                auto solver = makeMethod(method, scene, facesAsPatches(scene), unoccluded(1e-5, 1e-5),
                                         {0.5 * g.a, 0.5 * g.b, 0.1 * g.c}, {0.5 * g.a, 0.5 * g.b, g.c});
                solve(*solver);
                // The closed form treats each plate as uniform; the true radiosity is not, which
                // moves the means by a fraction of rho1 rho2 F^2 (< 5%): 0.5% covers it.
                CHECK(solver->solution()[0].x == doctest::Approx((E1 + rho1 * F * E2) / denominator).epsilon(5e-3).scale(0));
                CHECK(solver->solution()[1].x == doctest::Approx((E2 + rho2 * F * E1) / denominator).epsilon(5e-3).scale(0));
            }
        }
    }
}

// ctest-case-labels: heavy
TEST_CASE("hierarchical: energy balance (1 - rho) sum A B = sum A E in a closed box") {
    for (const double rho : {0.7}) {
        // Only the ceiling emits, per band differently: radiosity is far from uniform.
        std::vector<Material> materials = {{"wall", Rgb(rho), ExitanceRgb{}},
                                           {"lamp", Rgb(rho), ExitanceRgb(Rgb(3.0, 2.0, 1.0))}};
        const Scene scene = makeClosedBox({1.5, 1, 2}, materials, {0, 1, 0, 0, 0, 0});
        for (const SolverMethod method : kHierarchicalMethods) {
            CAPTURE(methodName(method));
            auto solver = makeMethod(method, scene, facesAsPatches(scene), unoccluded(1e-5, 1e-4), {0.75, 0.5, 0.2},
                                     {0.75, 0.3, 2});
            CHECK(solve(*solver, 1e-5) < 300);
            const ElementTree& tree = solver->elements();
            Rgb reflected(0.0), emitted(0.0);
            for (const ElementIndex e : tree.leaves()) reflected += (1 - rho) * tree.area(e) * tree.radiosity()[e];
            for (const Surface& s : scene.surfaces) emitted += s.area() * scene.materials[s.material].exitance.value();
            for (int band = 0; band < 3; ++band)
                CHECK(reflected[band] == doctest::Approx(emitted[band]).epsilon(0.01).scale(0));
        }
    }
}

TEST_CASE("hierarchical: links refine more near the light than far from it") {
    // A 4 m x 4 m floor under a small lamp 0.5 m above one corner region.
    Scene scene;
    scene.materials = {greyMaterial("floor", 0.5, 0), greyMaterial("lamp", 0, 10)};
    scene.surfaces.push_back({"floor", 0, {makeFace({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}})}, "test"});
    scene.surfaces.push_back(
        {"lamp", 1, {makeFace({{0.75, 0.75, 0.5}, {0.75, 1.25, 0.5}, {1.25, 1.25, 0.5}, {1.25, 0.75, 0.5}})}, "test"});
    HierarchicalSolver solver(scene, facesAsPatches(scene), unoccluded(1e-4, 1e-6), nullptr);
    const IterationStats stats = solver.step();
    CHECK(stats.linksRefined > 0);
    CHECK(stats.links == solver.links().size());
    const ElementTree& tree = solver.elements();
    double nearArea = 0, farArea = 0;
    int nearCount = 0, farCount = 0;
    for (const ElementIndex e : tree.leaves()) {
        if (tree.surface(e) != 0) continue;
        const glm::dvec3 p = tree.polygon(e).centroid;
        const double distance = std::hypot(p.x - 1, p.y - 1);
        if (distance < 0.5) nearArea += tree.area(e), ++nearCount;
        if (distance > 2.5) farArea += tree.area(e), ++farCount;
    }
    REQUIRE(nearCount > 0);
    REQUIRE(farCount > 0);
    CHECK(nearArea / nearCount < 0.1 * farArea / farCount);
}

TEST_CASE("hierarchical: setMaterial keeps the links and resumes to the fresh answer") {
    const double a = 1, b = 1, c = 1;
    const double F = radiant::test::parallelRectangles(a, b, c);
    const Scene before = makePlates(a, b, c, greyMaterial("emitter", 0, 1), greyMaterial("receiver", 0.3, 0));
    const Scene after = makePlates(a, b, c, greyMaterial("emitter", 0, 2), greyMaterial("receiver", 0.7, 0));
    const glm::dvec3 eye{0.5, 0.5, 0.1}, target{0.5, 0.5, 1};
    for (const SolverMethod method : kHierarchicalMethods) {
        CAPTURE(methodName(method));
        auto resumed = makeMethod(method, before, facesAsPatches(before), unoccluded(1e-5, 1e-5), eye, target);
        solve(*resumed);
        const std::size_t linksBefore = resumed->links().size();
        resumed->setMaterial(0, Rgb(0), ExitanceRgb(Rgb(2)));
        resumed->setMaterial(1, Rgb(0.7), ExitanceRgb{});
        CHECK(resumed->links().size() == linksBefore);
        solve(*resumed);
        auto fresh = makeMethod(method, after, facesAsPatches(after), unoccluded(1e-5, 1e-5), eye, target);
        solve(*fresh);
        CHECK(resumed->solution()[1].x == doctest::Approx(0.7 * F * 2).epsilon(2e-3).scale(0));
        CHECK(resumed->solution()[1].x == doctest::Approx(fresh->solution()[1].x).epsilon(2e-3).scale(0));
        CHECK_THROWS_AS(resumed->setMaterial(5, Rgb(0.5), ExitanceRgb{}), RadiantError);
        CHECK_THROWS_AS(resumed->setMaterial(0, Rgb(1.0), ExitanceRgb{}), RadiantError);
    }
}

TEST_CASE("hierarchical: reset and solve again gives the first solve's patches") {
    // A student who presses Reset and runs again must read the same numbers. Reset keeps the links
    // and the rows (the form factors, Solver::reset), so the second solve iterates the same operator
    // from B = E to the same fixed point; with the links re-refined from where the first solve left
    // them (before 2026-12-04) its elements split differently and 710 of the 741 patches moved.
    const Scene scene = makeCornellBox();
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.004;
    const PatchMesh mesh = meshScene(scene, meshing);
    for (const SolverMethod method : kHierarchicalMethods) {
        CAPTURE(methodName(method));
        auto solver = makeSolver(method, scene, mesh, SolverOptions{});
        solve(*solver, 1e-7);
        const std::vector<Rgb> first(solver->solution().begin(), solver->solution().end());
        const std::size_t links = solver->lastStats().links;
        solver->reset();
        solve(*solver, 1e-7);
        CHECK(solver->lastStats().links == links);
        double worst = 0;
        for (std::size_t i = 0; i < first.size(); ++i)
            for (int band = 0; band < 3; ++band)
                if (first[i][band] > 1e-6) worst = std::max(worst, std::abs(solver->solution()[i][band] / first[i][band] - 1));
        MESSAGE("largest relative change of a patch's band " << worst);
        CHECK(worst < 1e-4);
    }
}

TEST_CASE("hierarchical: the meshed Cornell box shows each patch the leaves under it") {
    const Scene scene = makeCornellBox();
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.01;
    const PatchMesh mesh = meshScene(scene, meshing);
    SolverOptions options;
    options.linkEpsilon = 1e-4;
    Progress progress;
    auto solver = makeSolver(SolverMethod::Hierarchical, scene, mesh, options, &progress);
    CHECK(progress.done == progress.total);
    CHECK(solve(*solver, 1e-3, 100) < 100);
    const auto& solution = solver->solution();
    REQUIRE(solution.size() == mesh.size());
    const auto& hierarchical = dynamic_cast<const HierarchicalSolver&>(*solver);
    const ElementTree& tree = hierarchical.elements();
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        CAPTURE(scene.surfaces[s].name);
        // The patches' area-weighted mean is the leaves' (both tile the surface).
        Rgb patchSum(0.0), leafSum(0.0);
        for (std::uint32_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
            // Only the floor's patches wholly under a block (cut along the footprints) see nothing.
            if (scene.surfaces[s].name != "floor") CHECK(solution[i].x > 0);
            patchSum += mesh.patches[i].area * solution[i];
        }
        for (const ElementIndex e : tree.leaves())
            if (tree.surface(e) == s) leafSum += tree.area(e) * tree.radiosity()[e];
        CHECK(patchSum.x == doctest::Approx(leafSum.x).epsilon(0.03).scale(0));
    }
    solver->reset();
    CHECK(solver->lastStats().iteration == 0);
    const std::size_t light = scene.findSurface("light");
    for (std::size_t i = 0; i < mesh.size(); ++i)
        CHECK(solution[i].x == (mesh.patches[i].surface == light ? 17.0 : 0.0));
}

TEST_CASE("importance: zero where the camera cannot see, positive in view") {
    Scene scene = makeCornellBox();
    // A plate behind the Cornell camera, facing away from the box: neither seen nor lit.
    scene.surfaces.push_back(
        {"behind", 0, {makeFace({{0.1, 0.1, -1.2}, {0.1, 0.4, -1.2}, {0.4, 0.4, -1.2}, {0.4, 0.1, -1.2}})}, "test"});
    REQUIRE(scene.surfaces.back().faces[0].normal.z < 0);
    SolverOptions options;  // the scene is named cornell-box: its home view is the Cornell camera
    const PatchMesh mesh = facesAsPatches(scene);
    ImportanceSolver solver(scene, mesh, options, nullptr);
    for (int k = 0; k < 10; ++k) solver.step();
    const auto& emitted = solver.emittedImportance();
    const auto& importance = solver.importance();
    REQUIRE(emitted.size() == mesh.size());
    int seen = 0, turnedAway = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Patch& patch = mesh.patches[i];
        const std::string& name = scene.surfaces[patch.surface].name;
        CAPTURE(name);
        CHECK(emitted[i] >= 0);
        // Faces turned away from the eye cannot receive eye rays (a geometric fact, not the code's).
        if (glm::dot(patch.normal, cornellView().eye - patch.centroid) <= 0) {
            CHECK(emitted[i] == 0);
            ++turnedAway;
        }
        // Not the floor since its elements start from its pieces cut along the blocks' footprints
        // (ContactCuts.h): one patch here over many roots, it read 0 (not traced further: a mesh of
        // whole faces is this test's alone; meshScene's patches lie within the pieces).
        if (name == "back wall" || name == "ceiling" || name == "left wall" ||
            name == "right wall") {
            CHECK(emitted[i] > 0);
            CHECK(importance[i] >= emitted[i]);
            ++seen;
        }
        if (name == "behind") CHECK(importance[i] == 0);
    }
    CHECK(seen > 5);
    CHECK(turnedAway >= 2);  // the blocks' back sides
    // The share of eye rays that hit something is at most the whole image.
    double share = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) share += emitted[i] * mesh.patches[i].area;
    CHECK(share > 0.5);
    CHECK(share <= 1.0 + 1e-12);
}

TEST_CASE("importance: the adjoint identity sum A r B = sum A E Y") {
    // Grey materials (importance carries one band) in the Cornell geometry.
    Scene scene = makeCornellBox();
    for (Material& m : scene.materials) {
        m.reflectance = Rgb(m.emits() ? 0.2 : 0.6);
        if (m.emits()) m.exitance = ExitanceRgb(Rgb(10.0));
    }
    SolverOptions options;
    options.linkEpsilon = 1e-4;
    ImportanceSolver solver(scene, facesAsPatches(scene), options, nullptr);
    solve(solver, 1e-9, 200);
    for (int k = 0; k < 40; ++k) solver.step();  // the importance iteration converges like the radiosity one
    const Rgb image = solver.imageResponse();
    const Rgb adjoint = solver.adjointResponse();
    CHECK(image.x > 0);
    // Exact for the exact solutions; the links p <- q and q <- p are refined separately, so the
    // discrete operators are transposes only up to the refinement tolerance; and once the links
    // settle, radiosity gathers through rows that cast their own rays per term of a partly visible
    // link (HierarchicalGather.cpp), which the importance iteration's transpose does not: measured
    // 0.50% apart since (2026-12-02, with the floor cut along the blocks' footprints), 1% allowed.
    CHECK(adjoint.x == doctest::Approx(image.x).epsilon(0.01).scale(0));
    MESSAGE("image " << image.x << " W/m^2, adjoint " << adjoint.x << " W/m^2");
}

TEST_CASE("importance: refinement follows the camera") {
    // Two identical closed boxes side by side lit alike; the camera looks into the first only.
    // Importance-driven refinement spends its elements there.
    Scene scene;
    scene.materials = {greyMaterial("wall", 0.5, 0), greyMaterial("lamp", 0.5, 5)};
    for (const double offset : {0.0, 5.0}) {
        const Scene box = makeClosedBox({1, 1, 1}, scene.materials, {0, 1, 0, 0, 0, 0});
        for (Surface surface : box.surfaces) {
            for (Face& face : surface.faces) {
                for (glm::dvec3& v : face.vertices) v.x += offset;
                face.updateGeometry();
            }
            scene.surfaces.push_back(surface);
        }
    }
    SolverOptions options = unoccluded(1e-4, 1e-5);
    options.formFactors.visibilityRays = 4;  // the boxes hide each other
    auto solver = makeMethod(SolverMethod::Importance, scene, facesAsPatches(scene), options, {0.5, 0.5, 0.05},
                             {0.5, 0.5, 1});
    for (int k = 0; k < 5; ++k) solver->step();
    const ElementTree& tree = solver->elements();
    std::size_t inView = 0, outOfView = 0;
    for (const ElementIndex e : tree.leaves()) (tree.polygon(e).centroid.x < 2.5 ? inView : outOfView)++;
    CHECK(inView > 4 * outOfView);
    MESSAGE(inView << " leaves in the seen box, " << outOfView << " in the other");
}

} // TEST_SUITE

TEST_CASE("hierarchical: links between elements no blocker can come between cast no rays") {
    // The closed furnace is convex: no face can block a segment between two of its points, so no
    // occluder's box meets any pair's and its links take full visibility without rays; the answer
    // stays E / (1 - rho) = 2. The Cornell box's blocks stand between some pairs: those cast rays.
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.05;
    const Scene furnace = makeFurnace();
    auto solver = makeSolver(SolverMethod::Hierarchical, furnace, meshScene(furnace, meshing));
    for (int step = 0; step < 300 && solver->step().residual > 1e-6; ++step) {}
    REQUIRE(solver->hierarchy() != nullptr);
    CHECK(solver->hierarchy()->raysCast() == 0);
    const ElementTree& tree = solver->hierarchy()->elements();
    double sum = 0;
    for (const ElementIndex e : tree.leaves()) sum += tree.area(e) * tree.radiosity()[e].x;
    CHECK(sum / furnace.totalArea() == doctest::Approx(2.0).epsilon(0.005).scale(0));

    const Scene cornell = makeCornellBox();
    meshing.maxPatchArea = 0.01;
    auto blocked = makeSolver(SolverMethod::Hierarchical, cornell, meshScene(cornell, meshing));
    blocked->step();
    CHECK(blocked->hierarchy()->raysCast() > 0);
}
