// ctest-labels: threads
// The gathering and shooting solvers against closed forms (docs/reference.md): the furnace, Jacobi's
// iterates, two-patch exchange, energy balance. Meshes here are built by hand with form factors
// from the published closed forms, so the solvers are tested independently of the kernel.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/ProgressiveSolver.h"
#include "radiometry/solver/SolverFactories.h"

#include "tests/support/CatalogViewFactors.h"

using namespace radiant;
using radiant::test::parallelRectangles;
using radiant::test::perpendicularRectangles;

namespace {




/// A scene whose surfaces are single patches with given areas, one material per surface, and a
/// dense form-factor matrix given by hand. The patches carry no geometry: the solvers see only
/// areas, materials and form factors.
struct HandBuilt {
    Scene scene;
    PatchMesh mesh;
    std::vector<std::vector<double>> F;  ///< F[i][j], patch i to patch j

    HandBuilt(const std::vector<double>& areas, std::vector<std::vector<double>> factors) : F(std::move(factors)) {
        scene.name = "hand-built";
        mesh.surfaceFirstPatch.push_back(0);
        for (std::size_t i = 0; i < areas.size(); ++i) {
            scene.materials.push_back({"m" + std::to_string(i), Rgb(0.0), ExitanceRgb{}});
            scene.surfaces.push_back({"s" + std::to_string(i), i, {}, "test"});
            Patch patch;
            patch.surface = static_cast<std::uint32_t>(i);
            patch.area = areas[i];
            mesh.patches.push_back(patch);
            mesh.surfaceFirstPatch.push_back(static_cast<std::uint32_t>(i + 1));
        }
    }
    void material(std::size_t surface, Rgb reflectance, Rgb exitance) {
        scene.materials[surface].reflectance = reflectance;
        scene.materials[surface].exitance = ExitanceRgb(exitance);
    }
    [[nodiscard]] std::shared_ptr<const FormFactorMatrix> matrix() const {
        std::vector<std::vector<FormFactorEntry>> rows(F.size());
        for (std::size_t i = 0; i < F.size(); ++i)
            for (std::size_t j = 0; j < F.size(); ++j)
                if (F[i][j] != 0) rows[i].push_back({static_cast<std::uint32_t>(j), static_cast<float>(F[i][j])});
        return std::make_shared<const FormFactorMatrix>(std::move(rows));
    }
    [[nodiscard]] ShotFormFactors shot() const {
        return [factors = F](std::size_t shooter, std::uint32_t, std::span<double> toShooter) {
            for (std::size_t j = 0; j < toShooter.size(); ++j) toShooter[j] = factors[j][shooter];
        };
    }
    [[nodiscard]] std::unique_ptr<Solver> solver(SolverMethod method) const {
        switch (method) {
        case SolverMethod::Jacobi: return makeJacobiSolver(scene, mesh, matrix());
        case SolverMethod::GaussSeidel: return makeGaussSeidelSolver(scene, mesh, matrix());
        default: return makeProgressiveSolver(scene, mesh, shot());
        }
    }
};

/// A unit cube's six faces as patches: opposite faces (0,1), (2,3), (4,5).
HandBuilt unitCube() {
    const double opposite = parallelRectangles(1, 1, 1), adjacent = perpendicularRectangles(1, 1, 1);
    std::vector<std::vector<double>> F(6, std::vector<double>(6, adjacent));
    for (std::size_t i = 0; i < 6; ++i) {
        F[i][i] = 0;
        F[i][i ^ 1u] = opposite;
    }
    return HandBuilt(std::vector<double>(6, 1.0), F);
}

const SolverMethod kMethods[] = {SolverMethod::Jacobi, SolverMethod::GaussSeidel, SolverMethod::Progressive};

void solveTo(Solver& solver, double residual, std::size_t maxSteps = 100000) {
    for (std::size_t k = 0; k < maxSteps && solver.lastStats().residual > residual; ++k) solver.step();
    REQUIRE(solver.lastStats().residual <= residual);
}

/// The residual by its definition (Solver.h), from the dense matrix.
double residualByDefinition(const HandBuilt& h, const std::vector<Rgb>& B) {
    Rgb power(0.0), emitted(0.0);
    for (std::size_t i = 0; i < B.size(); ++i) {
        const Material& m = h.scene.materials[i];
        Rgb gathered(0.0);
        for (std::size_t j = 0; j < B.size(); ++j) gathered += h.F[i][j] * B[j];
        power += h.mesh.patches[i].area * glm::abs(B[i] - m.exitance.value() - m.reflectance * gathered);
        emitted += h.mesh.patches[i].area * m.exitance.value();
    }
    return std::max({power.x / emitted.x, power.y / emitted.y, power.z / emitted.z});
}

/// Largest |row sum - 1| of the matrix as the solver stores it (float entries).
double rowSumDeviation(const FormFactorMatrix& matrix) {
    double worst = 0;
    for (std::size_t i = 0; i < matrix.size(); ++i) worst = std::max(worst, std::abs(matrix.rowSum(i) - 1.0));
    return worst;
}

/// A face from corners, wound so its normal points towards `inside`.
Face faceFacing(std::vector<glm::dvec3> corners, const glm::dvec3& inside) {
    Face face;
    face.vertices = std::move(corners);
    face.updateGeometry();
    if (glm::dot(face.normal, inside - face.vertices[0]) < 0) {
        std::reverse(face.vertices.begin(), face.vertices.end());
        face.updateGeometry();
    }
    return face;
}

/// An axis-aligned box [0,w] x [0,h] x [0,d] seen from inside, one surface per face, in the order
/// x=0, x=w, y=0, y=h, z=0, z=d; every face of material 0 except `emitter` (material 1).
Scene closedBox(double w, double h, double d, std::size_t emitter, Material plain, Material emitting) {
    Scene scene;
    scene.name = "test box";
    scene.materials = {std::move(plain), std::move(emitting)};
    const glm::dvec3 centre(w / 2, h / 2, d / 2);
    const std::vector<std::vector<glm::dvec3>> faces = {
        {{0, 0, 0}, {0, h, 0}, {0, h, d}, {0, 0, d}}, {{w, 0, 0}, {w, h, 0}, {w, h, d}, {w, 0, d}},
        {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}}, {{0, h, 0}, {w, h, 0}, {w, h, d}, {0, h, d}},
        {{0, 0, 0}, {w, 0, 0}, {w, h, 0}, {0, h, 0}}, {{0, 0, d}, {w, 0, d}, {w, h, d}, {0, h, d}}};
    for (std::size_t f = 0; f < faces.size(); ++f)
        scene.surfaces.push_back({"face " + std::to_string(f), f == emitter ? 1u : 0u, {faceFacing(faces[f], centre)}, "test"});
    return scene;
}

PatchMesh meshAt(const Scene& scene, double maxPatchArea) {
    MeshingOptions options;
    options.maxPatchArea = maxPatchArea;
    return meshScene(scene, options);
}

/// Area-weighted mean radiosity per surface.
std::vector<Rgb> surfaceMeans(const PatchMesh& mesh, const std::vector<Rgb>& B) {
    std::vector<Rgb> means;
    for (std::size_t s = 0; s + 1 < mesh.surfaceFirstPatch.size(); ++s) {
        Rgb power(0.0);
        double area = 0;
        for (std::size_t i = mesh.surfaceFirstPatch[s]; i < mesh.surfaceFirstPatch[s + 1]; ++i) {
            power += mesh.patches[i].area * B[i];
            area += mesh.patches[i].area;
        }
        means.push_back(power / area);
    }
    return means;
}

} // namespace

TEST_SUITE("solvers") {

TEST_CASE("the closed forms used as oracles reproduce their published values") {
    CHECK(parallelRectangles(1, 1, 1) == doctest::Approx(0.199825).epsilon(1e-5).scale(0));
    CHECK(parallelRectangles(1, 1.5, 0.5) == doctest::Approx(0.4756).epsilon(1e-3).scale(0));
    CHECK(perpendicularRectangles(1, 1, 1) == doctest::Approx(0.200044).epsilon(1e-5).scale(0));
}

TEST_CASE("every method converges to E/(1-rho) in the furnace") {
    for (const double rho : {0.3, 0.7, 0.9}) {
        HandBuilt cube = unitCube();
        const Rgb exitance(2.0, 1.0, 0.5);
        for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(rho), exitance);
        const double deviation = rowSumDeviation(*cube.matrix());
        REQUIRE(deviation < 1e-5);
        for (const SolverMethod method : kMethods) {
            CAPTURE(methodName(method));
            CAPTURE(rho);
            auto solver = cube.solver(method);
            solveTo(*solver, 1e-10);
            // With row sums 1 + d the fixed point is E / (1 - rho (1 + d)) at worst.
            const double tolerance = rho * deviation / (1 - rho * (1 + deviation)) + 1e-8;
            for (const Rgb& B : solver->solution())
                for (int band = 0; band < 3; ++band)
                    CHECK(B[band] == doctest::Approx(exitance[band] / (1 - rho)).epsilon(tolerance).scale(0));
        }
    }
}

TEST_CASE("Jacobi's k-th furnace iterate is E (1 - rho^(k+1)) / (1 - rho)") {
    for (const double rho : {0.5, 0.8}) {
        HandBuilt cube = unitCube();
        const double exitance = 3.0;
        for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(rho), Rgb(exitance));
        const auto matrix = cube.matrix();
        const double d = rowSumDeviation(*matrix);
        REQUIRE(d < 1e-5);
        auto solver = makeJacobiSolver(cube.scene, cube.mesh, matrix);
        for (std::size_t k = 1; k <= 30; ++k) {
            solver->step();
            REQUIRE(solver->lastStats().iteration == k);
            // Bounce m sees (F^m 1) within (1 + d)^m - 1 of 1.
            double tolerance = 1e-12;
            for (std::size_t m = 1; m <= k; ++m)
                tolerance += exitance * std::pow(rho, static_cast<double>(m)) * (std::pow(1 + d, static_cast<double>(m)) - 1);
            const double expected = exitance * (1 - std::pow(rho, static_cast<double>(k + 1))) / (1 - rho);
            for (const Rgb& B : solver->solution()) CHECK(std::abs(B.x - expected) <= tolerance);
        }
    }
}

TEST_CASE("two patches exchange light as the closed form says") {
    struct Plates {
        double a, b, c;
    };
    for (const Plates p : {Plates{1, 1, 1}, Plates{1, 1.5, 0.5}, Plates{2, 0.5, 0.3}}) {
        const double F = parallelRectangles(p.a, p.b, p.c);  // F12 = F21: equal areas
        HandBuilt plates({p.a * p.b, p.a * p.b}, {{0, F}, {F, 0}});
        const Rgb rho1(0.8, 0.5, 0.2), rho2(0.6, 0.9, 0.4), e1(10, 5, 1), e2(0, 2, 7);
        plates.material(0, rho1, e1);
        plates.material(1, rho2, e2);
        const Rgb denominator = Rgb(1.0) - rho1 * rho2 * F * F;
        const Rgb b1 = (e1 + rho1 * F * e2) / denominator;
        const Rgb b2 = (e2 + rho2 * F * e1) / denominator;
        for (const SolverMethod method : kMethods) {
            CAPTURE(methodName(method));
            CAPTURE(p.c);
            auto solver = plates.solver(method);
            solveTo(*solver, 1e-12);
            for (int band = 0; band < 3; ++band) {
                // float storage of F limits agreement to about 1e-7 relative.
                CHECK(solver->solution()[0][band] == doctest::Approx(b1[band]).epsilon(1e-6).scale(0));
                CHECK(solver->solution()[1][band] == doctest::Approx(b2[band]).epsilon(1e-6).scale(0));
            }
        }
    }
}

TEST_CASE("a closed box with uniform reflectance balances emitted and absorbed power") {
    for (const double rho : {0.4, 0.85}) {
        HandBuilt cube = unitCube();
        for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(rho), Rgb(0.0));
        cube.material(2, Rgb(rho), Rgb(5.0, 1.0, 0.0));  // one face emits, one band stays dark
        const double deviation = rowSumDeviation(*cube.matrix());
        for (const SolverMethod method : kMethods) {
            CAPTURE(methodName(method));
            auto solver = cube.solver(method);
            solveTo(*solver, 1e-11);
            Rgb absorbed(0.0);
            for (const Rgb& B : solver->solution()) absorbed += (1 - rho) * B;  // unit areas
            const double tolerance = rho * deviation / (1 - rho * (1 + deviation)) + 1e-9;
            CHECK(absorbed.x == doctest::Approx(5.0).epsilon(tolerance).scale(0));
            CHECK(absorbed.y == doctest::Approx(1.0).epsilon(tolerance).scale(0));
            CHECK(absorbed.z == 0.0);
        }
    }
}

TEST_CASE("gathering residuals follow their definition and the shooting residual bounds it") {
    HandBuilt cube = unitCube();
    const Rgb rho[] = {{0.7, 0.6, 0.5}, {0.2, 0.8, 0.4}, {0.5, 0.5, 0.5}, {0.9, 0.1, 0.3}, {0.6, 0.6, 0.2}, {0.3, 0.3, 0.9}};
    for (std::size_t s = 0; s < 6; ++s) cube.material(s, rho[s], s == 4 ? Rgb(4, 3, 2) : Rgb(0.0));
    for (const SolverMethod method : kMethods) {
        CAPTURE(methodName(method));
        auto solver = cube.solver(method);
        CHECK(solver->lastStats().iteration == 0);
        for (int k = 0; k < 6; ++k) {
            const IterationStats stats = solver->step();
            const double defined = residualByDefinition(cube, solver->solution());
            if (method == SolverMethod::Progressive)
                CHECK(stats.residual >= defined * (1 - 1e-9));
            else
                CHECK(stats.residual == doctest::Approx(defined).epsilon(1e-4).scale(0));  // float form factors
        }
    }
}

TEST_CASE("setMaterial resumes to the answer of a fresh solve with the new material") {
    HandBuilt cube = unitCube();
    for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(0.5, 0.6, 0.7), Rgb(0.0));
    cube.material(0, Rgb(0.3), Rgb(8, 6, 4));
    HandBuilt edited = cube;
    edited.material(3, Rgb(0.9, 0.1, 0.4), Rgb(0, 1, 0));  // brighter and darker bands at once
    edited.material(0, Rgb(0.3), Rgb(2, 6, 1));             // the light dims: negative unshot light
    for (const SolverMethod method : kMethods) {
        CAPTURE(methodName(method));
        auto resumed = cube.solver(method);
        solveTo(*resumed, 1e-3);
        resumed->setMaterial(3, Rgb(0.9, 0.1, 0.4), ExitanceRgb(Rgb(0, 1, 0)));
        resumed->setMaterial(0, Rgb(0.3), ExitanceRgb(Rgb(2, 6, 1)));
        solveTo(*resumed, 1e-12);
        auto fresh = edited.solver(method);
        solveTo(*fresh, 1e-12);
        for (std::size_t i = 0; i < 6; ++i)
            for (int band = 0; band < 3; ++band)
                CHECK(resumed->solution()[i][band] == doctest::Approx(fresh->solution()[i][band]).epsilon(1e-9).scale(0));
    }
}

TEST_CASE("setMaterial refuses reflectance of 1 or more, negative reflectance and unknown surfaces") {
    HandBuilt cube = unitCube();
    cube.material(0, Rgb(0.5), Rgb(1.0));
    for (const SolverMethod method : kMethods) {
        auto solver = cube.solver(method);
        CHECK_THROWS_AS(solver->setMaterial(1, Rgb(1.0, 0.5, 0.5), ExitanceRgb{}), RadiantError);
        CHECK_THROWS_AS(solver->setMaterial(1, Rgb(0.5), ExitanceRgb(Rgb(-1, 0, 0))), RadiantError);
        CHECK_THROWS_AS(solver->setMaterial(6, Rgb(0.5), ExitanceRgb{}), RadiantError);
    }
}

TEST_CASE("reset returns to iteration 0 and B = E") {
    HandBuilt cube = unitCube();
    for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(0.6), Rgb(0.0));
    cube.material(1, Rgb(0.6), Rgb(1, 2, 3));
    for (const SolverMethod method : kMethods) {
        CAPTURE(methodName(method));
        auto solver = cube.solver(method);
        const IterationStats initial = solver->lastStats();
        for (int k = 0; k < 5; ++k) solver->step();
        solver->reset();
        CHECK(solver->lastStats().iteration == 0);
        CHECK(solver->lastStats().residual == doctest::Approx(initial.residual).scale(0));
        for (std::size_t i = 0; i < 6; ++i) CHECK(solver->solution()[i] == cube.scene.materials[i].exitance.value());
        // And it runs again the same way.
        solver->step();
        CHECK(solver->lastStats().iteration == 1);
    }
}

TEST_CASE("progressive shoots the patch with the most unshot power and keeps the ambient estimate sensible") {
    HandBuilt cube = unitCube();
    for (std::size_t s = 0; s < 6; ++s) cube.material(s, Rgb(0.5), Rgb(0.0));
    cube.material(2, Rgb(0.5), Rgb(1.0));
    cube.material(5, Rgb(0.5), Rgb(3.0));
    auto solver = makeProgressiveSolver(cube.scene, cube.mesh, cube.shot());
    CHECK(solver->step().shooter == 5);
    CHECK(solver->step().shooter == 2);
    // The ambient term: unshot power over the area, reflected 1/(1 - rho) times, so that adding it
    // to every patch puts the total power at the furnace's (sum A E) / (1 - rho) at once.
    const std::vector<Rgb> shown = solver->solutionWithAmbient();
    double shownPower = 0, unshotPower = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        shownPower += shown[i].x;
        unshotPower += solver->unshot()[i].x;
    }
    CHECK(solver->ambient().x == doctest::Approx(unshotPower / 6 / (1 - 0.5)).scale(0));
    CHECK(shownPower > 0);
}

// ---- With the real mesher and form-factor kernel --------------------------------------------

TEST_CASE("the computed matrix sums to the face-to-face closed forms of a box") {
    for (const auto& values : {std::array{1.0, 1.0, 1.0}, std::array{2.0, 1.0, 0.5}}) {
        const double w = values[0], h = values[1], d = values[2];  // not a structured binding: clang 14 cannot CAPTURE those
        const Scene box = closedBox(w, h, d, 0, {"grey", Rgb(0.5), ExitanceRgb{}}, {"lamp", Rgb(0.5), ExitanceRgb(Rgb(1.0))});
        const PatchMesh mesh = meshAt(box, w * h * d / 12);
        const RayCaster rays(box);
        Progress progress;
        const FormFactorMatrix matrix = FormFactorMatrix::compute(mesh, &rays, {}, 0.0, &progress);
        CHECK(progress.fraction() == doctest::Approx(1.0).scale(0));
        CHECK(matrix.stats().pairsCulled > 0);  // coplanar pairs on every face
        // Face x=0 (w-side... its extent is h x d) to x=w: opposed h x d at distance w; to y=0:
        // perpendicular, sharing the edge of length d, with widths h (from) and w (to).
        const auto faceToFace = [&](std::size_t from, std::size_t to) {
            double flux = 0, area = 0;
            for (std::size_t i = mesh.surfaceFirstPatch[from]; i < mesh.surfaceFirstPatch[from + 1]; ++i) {
                area += mesh.patches[i].area;
                for (const FormFactorEntry& e : matrix.row(i))
                    if (mesh.patches[e.column].surface == to) flux += mesh.patches[i].area * e.value;
            }
            return flux / area;
        };
        CAPTURE(w);
        CHECK(faceToFace(0, 1) == doctest::Approx(parallelRectangles(h, d, w)).epsilon(3e-3).scale(0));
        CHECK(faceToFace(1, 0) == doctest::Approx(parallelRectangles(h, d, w)).epsilon(3e-3).scale(0));
        CHECK(faceToFace(0, 2) == doctest::Approx(perpendicularRectangles(h, w, d)).epsilon(3e-3).scale(0));
        CHECK(faceToFace(2, 0) == doctest::Approx(perpendicularRectangles(w, h, d)).epsilon(3e-3).scale(0));
        CHECK(faceToFace(4, 5) == doctest::Approx(parallelRectangles(w, h, d)).epsilon(3e-3).scale(0));
        for (std::size_t i = 0; i < matrix.size(); ++i) CHECK(matrix.rowSum(i) == doctest::Approx(1.0).epsilon(5e-3).scale(0));
    }
}

TEST_CASE("meshed furnace with the real kernel: every method reaches E/(1-rho) to its row sums") {
    const double rho = 0.6;
    const Material wall{"wall", Rgb(rho), ExitanceRgb(Rgb(1.0, 2.0, 3.0))};
    const Scene box = closedBox(1.0, 0.8, 1.2, 0, wall, wall);
    const PatchMesh mesh = meshAt(box, 0.08);
    const auto matrix = computeFormFactorMatrix(box, mesh, {}, nullptr);
    double deviation = 0;
    for (std::size_t i = 0; i < matrix->size(); ++i) deviation = std::max(deviation, std::abs(matrix->rowSum(i) - 1));
    REQUIRE(deviation < 1e-2);
    // The progressive route computes its own factors per shot; measure its closure the same way:
    // row j of what it uses is sum over shooters s of F_{j->s}.
    const ShotFormFactors shot = makeRayCastShotFormFactors(box, mesh, {});
    std::vector<double> shotRowSums(mesh.size(), 0.0), column(mesh.size());
    for (std::size_t s = 0; s < mesh.size(); ++s) {
        shot(s, 0, column);
        for (std::size_t j = 0; j < mesh.size(); ++j) shotRowSums[j] += column[j];
    }
    double shotDeviation = 0;
    for (const double sum : shotRowSums) shotDeviation = std::max(shotDeviation, std::abs(sum - 1));
    REQUIRE(shotDeviation < 2e-2);
    for (const SolverMethod method : kMethods) {
        CAPTURE(methodName(method));
        auto solver = method == SolverMethod::Progressive ? makeSolver(method, box, mesh)
                      : method == SolverMethod::Jacobi   ? makeJacobiSolver(box, mesh, matrix)
                                                          : makeGaussSeidelSolver(box, mesh, matrix);
        solveTo(*solver, 1e-6);
        const double d = method == SolverMethod::Progressive ? shotDeviation : deviation;
        const double tolerance = rho * d / (1 - rho * (1 + d)) + 1e-5;
        for (const Rgb& B : solver->solution()) {
            CHECK(B.x == doctest::Approx(1.0 / (1 - rho)).epsilon(tolerance).scale(0));
            CHECK(B.z == doctest::Approx(3.0 / (1 - rho)).epsilon(tolerance).scale(0));
        }
    }
}

TEST_CASE("two real plates exchange light as the closed form says") {
    for (const double gap : {1.0, 0.4}) {
        Scene plates;
        plates.name = "plates";
        plates.materials = {{"low", Rgb(0.7, 0.5, 0.3), ExitanceRgb(Rgb(5, 1, 0))}, {"high", Rgb(0.4, 0.6, 0.8), ExitanceRgb(Rgb(0, 2, 3))}};
        plates.surfaces.push_back({"low", 0, {faceFacing({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {0.5, 1, 0.5})}, "test"});
        plates.surfaces.push_back({"high", 1, {faceFacing({{0, gap, 0}, {1, gap, 0}, {1, gap, 1}, {0, gap, 1}}, {0.5, 0, 0.5})}, "test"});
        const PatchMesh mesh = meshAt(plates, 2.0);  // one patch each: the closed form is for whole plates
        REQUIRE(mesh.size() == 2);
        const double F = parallelRectangles(1, 1, gap);
        const Rgb rho1 = plates.materials[0].reflectance, rho2 = plates.materials[1].reflectance;
        const Rgb e1 = plates.materials[0].exitance.value(), e2 = plates.materials[1].exitance.value();
        const Rgb b1 = (e1 + rho1 * F * e2) / (Rgb(1.0) - rho1 * rho2 * F * F);
        for (const SolverMethod method : kMethods) {
            CAPTURE(methodName(method));
            CAPTURE(gap);
            auto solver = makeSolver(method, plates, mesh);
            solveTo(*solver, 1e-9);
            // The progressive far route takes the point kernel at the receiver's centroid: exact
            // only for small receivers, so whole plates go through the area quadrature there too.
            for (int band = 0; band < 3; ++band) CHECK(solver->solution()[0][band] == doctest::Approx(b1[band]).epsilon(3e-3).scale(0));
        }
    }
}

TEST_CASE("Cornell box: every method's surface means agree with a tight Gauss-Seidel reference") {
    const Scene cornell = makeCornellBox();
    const PatchMesh mesh = meshAt(cornell, 0.01);
    auto reference = makeSolver(SolverMethod::GaussSeidel, cornell, mesh);
    solveTo(*reference, 1e-9);
    const std::vector<Rgb> expected = surfaceMeans(mesh, reference->solution());
    for (const SolverMethod method : {SolverMethod::Jacobi, SolverMethod::Progressive, SolverMethod::Hierarchical,
                                      SolverMethod::Importance}) {
        CAPTURE(methodName(method));
        const std::unique_ptr<Solver> solver = makeSolver(method, cornell, mesh);
        solveTo(*solver, 1e-4, 20000);  // leaves < 0.1% of the emitted power unaccounted
        const std::vector<Rgb> means = surfaceMeans(mesh, solver->solution());
        // Relative, per band. Jacobi solves the same matrix. Hierarchical and importance refine their
        // own elements (within 2% of Gauss-Seidel's discretisation at this mesh); progressive's block
        // shooters treat a block's radiosity as uniform, which leaves surfaces up to 7% dark
        // (measured 2026-12-02; issue #14 asks for 1%, so this bound records the gap, not the goal).
        // Hierarchical: the blocks 2.7% bright since links whose rays all fell behind a horizon no longer
        // count as hidden (test_hierarchical_curved.cpp); their feet take the floor's mean, not its
        // shadow (docs/ARCHITECTURE.md, hierarchical term 2), so 3% records that gap too.
        const double tolerance = method == SolverMethod::Jacobi        ? 0.01
                                 : method == SolverMethod::Progressive  ? 0.08
                                 : method == SolverMethod::Hierarchical ? 0.03
                                                                        : 0.025;
        for (std::size_t s = 0; s < means.size(); ++s) {
            CAPTURE(cornell.surfaces[s].name);
            for (int band = 0; band < 3; ++band)
                CHECK(means[s][band] == doctest::Approx(expected[s][band]).epsilon(tolerance).scale(0));
        }
    }
}

TEST_CASE("a seed determines the solution, threads do not") {
    const Scene cornell = makeCornellBox();
    const PatchMesh mesh = meshAt(cornell, 0.03);
    for (const SolverMethod method : kMethods) {
        CAPTURE(methodName(method));
        SolverOptions options;
        options.seed = 7;
        auto first = makeSolver(method, cornell, mesh, options);
        auto second = makeSolver(method, cornell, mesh, options);
        for (int k = 0; k < 20; ++k) {
            first->step();
            second->step();
        }
        CHECK(first->solution() == second->solution());
        options.seed = 8;
        auto other = makeSolver(method, cornell, mesh, options);
        for (int k = 0; k < 20; ++k) other->step();
        CHECK(other->solution() != first->solution());  // the seed reaches the visibility rays
    }
}

} // TEST_SUITE
