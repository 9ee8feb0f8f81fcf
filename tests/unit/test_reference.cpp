// ctest-labels: threads
// The path-traced reference (radiometry/reference/) against closed forms from docs/reference.md: the
// furnace (B = E / (1 - rho) everywhere), direct light between parallel opposed rectangles (the
// differential-area-to-rectangle form factor, four corner rectangles summed), energy balance in a
// closed box ((1 - rho) sum A B = sum A M), and a converged Gauss-Seidel solve on fine meshes. Every
// comparison allows a few standard errors and also requires the standard error to be small, so a
// noisy or biased estimator fails. Seeds are fixed: the tests are deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/panels/PathTracedReading.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/reference/PathTracer.h"
#include "radiometry/reference/ReferencePoint.h"
#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "tests/support/CatalogViewFactors.h"
#include "radiometry/solver/Solver.h"

using namespace radiant;

namespace {


using test::pointToCornerRectangle;

/// The point-to-rectangle form factor of [x0, x1] x [y0, y1] at distance c.
double rectangleFormFactor(double x0, double x1, double y0, double y1, double c) {
    return test::overRectangle(pointToCornerRectangle, x0, x1, y0, y1, c);
}

Face quad(std::vector<glm::dvec3> corners) {
    Face face;
    face.vertices = std::move(corners);
    face.updateGeometry();
    return face;
}

/// Estimate at (x, n) with a fixed seed until the relative standard error reaches `precision`.
ReferenceEstimate estimateAt(const Scene& scene, const RayCaster& rays, const glm::dvec3& x, const glm::dvec3& n,
                             double precision, std::uint64_t seed = 7) {
    const PathTracer tracer(scene, rays);
    ReferenceRun run(tracer, locateReferencePoint(scene, x, n), {seed, 2, 2048});
    ReferenceStop stop;
    stop.relativeStandardError = precision;
    stop.samples = 4'000'000;  // a ceiling: a run that needs more fails the precision check below
    return run.runUntil(stop);
}

ReferenceStop stopAfter(std::uint64_t samples) {
    ReferenceStop stop;
    stop.samples = samples;
    return stop;
}

/// |value - expected| within `sigmas` standard errors, and the standard error itself at most
/// `precision` of the value (so that a wide error cannot pass a wrong value).
void checkWithin(double value, double standardError, double expected, double sigmas, double precision) {
    CAPTURE(value);
    CAPTURE(standardError);
    CAPTURE(expected);
    CHECK(std::abs(value - expected) <= sigmas * standardError);
    CHECK(standardError <= precision * std::abs(expected));
}

} // namespace

TEST_SUITE("reference") {

TEST_CASE("the furnace: B = M / (1 - rho) and E = B at every point, per band") {
    Scene furnace = makeFurnace();
    SUBCASE("rho 0.5 in every band") {}
    SUBCASE("a different rho per band, up to 0.85 (long paths: Russian roulette stays unbiased)") {
        furnace.materials[0].reflectance = Rgb(0.2, 0.5, 0.85);
        furnace.materials[0].exitance = ExitanceRgb(Rgb(1.0, 2.0, 0.5));
    }
    const Rgb rho = furnace.materials[0].reflectance;
    const Rgb M = furnace.materials[0].exitance.value();
    const RayCaster rays(furnace);
    // The furnace is [0,2] x [0,1] x [0,1.5]: a floor centre, a point near a corner, a wall, the ceiling.
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> points = {
        {{1.0, 0.0, 0.75}, {0, 1, 0}}, {{0.03, 0.0, 0.02}, {0, 1, 0}}, {{2.0, 0.4, 1.1}, {-1, 0, 0}},
        {{0.6, 1.0, 0.3}, {0, -1, 0}}};
    for (const auto& point : points) {
        const glm::dvec3& x = point.first;  // not a structured binding: CAPTURE's lambda needs a variable
        const glm::dvec3& n = point.second;
        CAPTURE(x);
        const ReferenceEstimate e = estimateAt(furnace, rays, x, n, 0.004);
        for (int band = 0; band < 3; ++band) {
            CAPTURE(band);
            const double expected = M[band] / (1 - rho[band]);
            checkWithin(e.radiosity.value()[band], e.radiosityStandardError[band], expected, 4, 0.005);
            checkWithin(e.irradiance.value()[band], e.irradianceStandardError[band], expected, 4, 0.005);
        }
    }
}

TEST_CASE("parallel opposed rectangles: E = M F(dA -> emitter), the catalog's corner form factors summed") {
    struct Plates {
        double a, b, c;  // emitter a x b at distance c
        double px, pz;   // receiver point, relative to the emitter's centre
    };
    const Plates cases[] = {{1, 1, 1, 0, 0}, {1, 1.5, 0.5, 0, 0}, {2, 0.5, 0.7, 0.3, -0.1}, {1, 1, 0.25, 0.45, 0.45}};
    for (const Plates& p : cases) {
        CAPTURE(p.a);
        CAPTURE(p.b);
        CAPTURE(p.c);
        CAPTURE(p.px);
        CAPTURE(p.pz);
        // A black emitter facing +y at y = 0 and a receiver facing -y at y = c: no interreflection,
        // so E at the receiver is direct light only and B = rho E.
        Scene scene;
        scene.name = "plates";
        const Rgb M(3.0, 1.0, 0.25);
        const Rgb rho(0.5, 0.3, 0.9);
        scene.materials = {{"emitter", Rgb(0.0), ExitanceRgb(M)}, {"receiver", rho, ExitanceRgb{}}};
        const double ha = p.a / 2, hb = p.b / 2;
        scene.surfaces.push_back({"emitter", 0, {quad({{-ha, 0, -hb}, {-ha, 0, hb}, {ha, 0, hb}, {ha, 0, -hb}})}, "test"});
        scene.surfaces.push_back(
            {"receiver", 1, {quad({{-ha, p.c, -hb}, {ha, p.c, -hb}, {ha, p.c, hb}, {-ha, p.c, hb}})}, "test"});
        REQUIRE(scene.surfaces[0].faces[0].normal.y == doctest::Approx(1).scale(0));
        REQUIRE(scene.surfaces[1].faces[0].normal.y == doctest::Approx(-1).scale(0));
        const RayCaster rays(scene);
        const ReferenceEstimate e = estimateAt(scene, rays, {p.px, p.c, p.pz}, {0, -1, 0}, 0.003);
        const double F = rectangleFormFactor(-ha - p.px, ha - p.px, -hb - p.pz, hb - p.pz, p.c);
        for (int band = 0; band < 3; ++band) {
            CAPTURE(band);
            checkWithin(e.irradiance.value()[band], e.irradianceStandardError[band], M[band] * F, 4, 0.004);
            checkWithin(e.radiosity.value()[band], e.radiosityStandardError[band], rho[band] * M[band] * F, 4, 0.004);
        }
    }
}

TEST_CASE("inside a closed box: a small ceiling emitter's direct light, and one bounce off the floor, by closed forms") {
    // The unit box [0,1]^3, every face inward; the ceiling (y = 1) a 3 x 3 grid of quads whose centre
    // [0.4, 0.6]^2 emits 1 W/m^2 per band, coplanar with the rest, as the Cornell box's light is.
    // Walls that absorb everything (the paths end there, through Russian roulette at weight 0), and
    // walls and an emitter in the shadow rays' way, as in a room: what the open plates above do not
    // test. Written while checking the Cornell box's accuracy table against Gauss-Seidel (issue 14):
    // the tracer holds here (direct light to a 0.05% standard error, one bounce to 0.2%, within 4 of them).
    const double a = 0.4, b = 0.6;
    const auto box = [&](const Rgb& floorRho) {
        Scene scene;
        scene.name = "closed box";
        scene.materials = {{"floor", floorRho, ExitanceRgb{}}, {"black", Rgb(0.0), ExitanceRgb{}},
                           {"light", Rgb(0.0), ExitanceRgb(Rgb(1.0))}};
        scene.surfaces.push_back({"floor", 0, {quad({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}})}, "test"});
        const double cut[] = {0, a, b, 1};
        std::vector<Face> ceiling;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                if (i != 1 || k != 1)
                    ceiling.push_back(quad({{cut[i], 1, cut[k]}, {cut[i + 1], 1, cut[k]}, {cut[i + 1], 1, cut[k + 1]},
                                            {cut[i], 1, cut[k + 1]}}));
        scene.surfaces.push_back({"ceiling", 1, std::move(ceiling), "test"});
        scene.surfaces.push_back({"light", 2, {quad({{a, 1, a}, {b, 1, a}, {b, 1, b}, {a, 1, b}})}, "test"});
        scene.surfaces.push_back({"x = 0", 1, {quad({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}})}, "test"});
        scene.surfaces.push_back({"x = 1", 1, {quad({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}})}, "test"});
        scene.surfaces.push_back({"z = 0", 1, {quad({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})}, "test"});
        scene.surfaces.push_back({"z = 1", 1, {quad({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}})}, "test"});
        return scene;
    };
    // F from a point of the floor (x, z) to the emitter 1 m above: four signed corner rectangles.
    const auto toEmitter = [&](double x, double z) { return rectangleFormFactor(a - x, b - x, a - z, b - z, 1.0); };

    SUBCASE("direct light on the floor: E = M F(dA -> emitter), also beside a wall and in a corner") {
        const Scene scene = box(Rgb(0.0));
        const RayCaster rays(scene);
        for (const auto& point : std::vector<std::pair<double, double>>{{0.5, 0.5}, {0.1, 0.85}, {0.02, 0.5}, {0.97, 0.03}}) {
            const double x = point.first, z = point.second;  // not a structured binding: CAPTURE's lambda takes them
            CAPTURE(x);
            CAPTURE(z);
            // Direct light alone: one shadow ray and one escaping path a sample, so 0.05% is cheap.
            const ReferenceEstimate e = estimateAt(scene, rays, {x, 0, z}, {0, 1, 0}, 0.0005);
            checkWithin(e.irradiance.value().x, e.irradianceStandardError.x, toEmitter(x, z), 4, 0.0006);
        }
    }
    SUBCASE("one bounce: a ceiling point sees only the floor (rho 0.5), E = integral of rho M F(y -> emitter) K(x, y) dA_y") {
        const double rho = 0.5;
        const Scene scene = box(Rgb(rho));
        const RayCaster rays(scene);
        // The floor's radiosity rho M F(y -> emitter) and the kernel h^2 / (pi r^4) between parallel
        // planes h = 1 apart are smooth: 8-point Gauss-Legendre on 16 x 16 panels is exact to ~1e-9.
        constexpr std::array<double, 8> node{0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                             0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                             0.8983332387068134, 0.9801449282487681};
        constexpr std::array<double, 8> weight{0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                               0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                               0.1111905172266872, 0.0506142681451881};
        constexpr int panels = 16;
        for (const auto& point : std::vector<std::pair<double, double>>{{0.3, 0.5}, {0.1, 0.1}}) {
            const double x = point.first, z = point.second;
            CAPTURE(x);
            CAPTURE(z);
            double expected = 0;
            for (int pu = 0; pu < panels; ++pu)
                for (int pv = 0; pv < panels; ++pv)
                    for (std::size_t i = 0; i < node.size(); ++i)
                        for (std::size_t k = 0; k < node.size(); ++k) {
                            const double yx = (pu + node[i]) / panels, yz = (pv + node[k]) / panels;
                            const double r2 = (yx - x) * (yx - x) + (yz - z) * (yz - z) + 1;
                            expected += weight[i] * weight[k] / (panels * panels) * rho * toEmitter(yx, yz) /
                                        (std::numbers::pi * r2 * r2);
                        }
            const ReferenceEstimate e = estimateAt(scene, rays, {x, 1, z}, {0, -1, 0}, 0.002);
            // The run stops at 0.2% of its own value, which may lie a little above the expected one.
            checkWithin(e.irradiance.value().x, e.irradianceStandardError.x, expected, 4, 0.0025);
        }
    }
}

TEST_CASE("a one-sided emitter lights only its front: a receiver facing its back gets nothing") {
    Scene scene;
    scene.name = "backs";
    scene.materials = {{"emitter", Rgb(0.0), ExitanceRgb(Rgb(1.0))}, {"receiver", Rgb(0.5), ExitanceRgb{}}};
    // The emitter faces -y, away from the receiver above it.
    scene.surfaces.push_back({"emitter", 0, {quad({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}})}, "test"});
    scene.surfaces.push_back({"receiver", 1, {quad({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}})}, "test"});
    const RayCaster rays(scene);
    const PathTracer tracer(scene, rays);
    ReferenceRun run(tracer, locateReferencePoint(scene, {0, 1, 0}, {0, -1, 0}), {3, 2, 1024});
    const ReferenceEstimate e = run.runUntil(stopAfter(20000));
    CHECK(e.samples == 20000);
    CHECK(e.irradiance.value() == Rgb(0.0));
    CHECK(e.irradianceStandardError == Rgb(0.0));
}

TEST_CASE("energy balance in a closed box: (1 - rho) times the area integral of B equals the emitted power") {
    // Each sample draws a point uniformly by area over the whole box and traces one path there, so
    // the sample mean of B estimates (1 / A) sum_i A_i B_i with an honest standard error.
    Scene cube = makeUnitCube();  // ceiling emits 1 W/m^2, rho 0.5 everywhere
    for (Material& material : cube.materials) material.reflectance = Rgb(0.5, 0.7, 0.3);
    const RayCaster rays(cube);
    const PathTracer tracer(cube, rays);
    double totalArea = 0;
    std::vector<double> cumulative;
    std::vector<std::size_t> surfaceOf;
    Rgb emitted(0.0);
    for (std::size_t s = 0; s < cube.surfaces.size(); ++s)
        for (const Face& face : cube.surfaces[s].faces) {
            totalArea += face.area;
            cumulative.push_back(totalArea);
            surfaceOf.push_back(s);
            emitted += face.area * cube.materials[cube.surfaces[s].material].exitance.value();
        }
    reference::RandomStream random(11, 0);
    ReferenceRun::Moments moments;
    const std::size_t samples = 400000;
    for (std::size_t k = 0; k < samples; ++k) {
        const double pick = random.uniform() * totalArea;
        const std::size_t f = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        const std::size_t s = surfaceOf[f];
        const Face& face = cube.surfaces[s].faces[0];  // one rectangle per surface
        const double u = random.uniform(), v = random.uniform();
        const glm::dvec3 x = face.vertices[0] + u * (face.vertices[1] - face.vertices[0]) + v * (face.vertices[3] - face.vertices[0]);
        const Rgb B = tracer.exitance(s) + tracer.reflectance(s) * tracer.sampleIrradiance(x, face.normal, random);
        moments.add(B);
    }
    const Rgb rho = cube.materials[0].reflectance;
    for (int band = 0; band < 3; ++band) {
        CAPTURE(band);
        const double absorbed = (1 - rho[band]) * totalArea * moments.mean[band];
        const double standardError = (1 - rho[band]) * totalArea *
                                     std::sqrt(moments.squaredDeviations[band] / double(samples - 1) / double(samples));
        checkWithin(absorbed, standardError, emitted[band], 4, 0.01);
    }
}

TEST_CASE("agrees with Gauss-Seidel on fine meshes where B is smooth, within 3 standard errors plus the mesh's own error") {
    // The mesh's discretisation error is taken as the change between a mesh and one with four times
    // as many patches: Gauss-Seidel's answer on the finer one is compared.
    const Scene cube = makeUnitCube();
    const RayCaster rays(cube);
    const auto solveOn = [&](double area) {
        MeshingOptions meshing;
        meshing.maxPatchArea = area;
        auto mesh = std::make_unique<PatchMesh>(meshScene(cube, meshing));
        auto solver = makeSolver(SolverMethod::GaussSeidel, cube, *mesh);
        for (int k = 0; k < 500 && solver->step().residual > 1e-9; ++k) {
        }
        REQUIRE(solver->lastStats().residual <= 1e-9);
        return std::pair{std::move(mesh), solver->solution()};
    };
    const auto [coarseMesh, coarse] = solveOn(0.02);
    const auto [fineMesh, fine] = solveOn(0.005);
    ProbeOptions probeOptions;
    probeOptions.gatherRaysPerSide = 16;
    const Probe coarseProbe(cube, *coarseMesh, &rays, probeOptions);
    const Probe fineProbe(cube, *fineMesh, &rays, probeOptions);
    // Centres and points between centre and edge; the walls' B varies slowly there.
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> points = {
        {{0.5, 0, 0.5}, {0, 1, 0}}, {{0.3, 0, 0.7}, {0, 1, 0}}, {{0, 0.5, 0.5}, {1, 0, 0}},
        {{0.5, 0.7, 1}, {0, 0, -1}}, {{0.5, 1, 0.5}, {0, -1, 0}}};
    for (const auto& point : points) {
        const glm::dvec3& x = point.first;  // not a structured binding: CAPTURE's lambda needs a variable
        const glm::dvec3& n = point.second;
        CAPTURE(x);
        const ReferenceEstimate e = estimateAt(cube, rays, x, n, 0.003);
        const ProbeReading atCoarse = coarseProbe.measure(x, n, coarse);
        const ProbeReading atFine = fineProbe.measure(x, n, fine);
        for (int band = 0; band < 3; ++band) {
            CAPTURE(band);
            const double b = atFine.radiosity.value()[band];
            const double bMesh = std::abs(b - atCoarse.radiosity.value()[band]);
            const double eValue = atFine.irradiance.value()[band];
            const double eMesh = std::abs(eValue - atCoarse.irradiance.value()[band]);
            CAPTURE(b);
            CAPTURE(bMesh);
            CHECK(std::abs(e.radiosity.value()[band] - b) <= 3 * e.radiosityStandardError[band] + bMesh);
            CHECK(std::abs(e.irradiance.value()[band] - eValue) <= 3 * e.irradianceStandardError[band] + eMesh);
            // The allowance must stay tight, or the check would pass anything.
            CHECK(3 * e.radiosityStandardError[band] + bMesh <= 0.02 * b);
        }
    }
}

TEST_CASE("a seed determines the estimate, the thread count does not") {
    const Scene cornell = makeCornellBox();
    const RayCaster rays(cornell);
    const PathTracer tracer(cornell, rays);
    const ReferencePoint at = locateReferencePoint(cornell, {0.15, 0, 0.4}, {0, 1, 0});
    const auto run = [&](std::uint64_t seed, unsigned threads) {
        ReferenceRun r(tracer, at, {seed, threads, 1000});
        return r.runUntil(stopAfter(5500));
    };
    const ReferenceEstimate one = run(5, 1), two = run(5, 2), three = run(5, 3), other = run(6, 2);
    CHECK(one.samples == 5500);
    CHECK(one.irradiance.value() == two.irradiance.value());
    CHECK(one.irradiance.value() == three.irradiance.value());
    CHECK(one.irradianceStandardError == three.irradianceStandardError);
    CHECK(other.irradiance.value() != one.irradiance.value());
}

TEST_CASE("a point on no surface, a zero normal and a normal facing away are errors naming the values") {
    const Scene cornell = makeCornellBox();
    CHECK_THROWS_WITH_AS((void)locateReferencePoint(cornell, {0.15, 0.4, 0.45}, {0, 1, 0}),
                         doctest::Contains("lies on no surface"), RadiantError);
    CHECK_THROWS_WITH_AS((void)locateReferencePoint(cornell, {0.15, 0, 0.4}, {0, 0, 0}), doctest::Contains("non-zero normal"),
                         RadiantError);
    CHECK_THROWS_WITH_AS((void)locateReferencePoint(cornell, {0.15, 0, 0.4}, {0, -1, 0}),
                         doctest::Contains("degrees from the front of surface 'floor'"), RadiantError);
    CHECK_THROWS_WITH_AS((void)locateReferencePoint(cornell, {0.15, 0, 0.4}, {1, 1, 0}), doctest::Contains("45 degrees"),
                         RadiantError);
    const ReferencePoint floor = locateReferencePoint(cornell, {0.15, 1e-6, 0.4}, {0.01, 1, 0});
    CHECK(cornell.surfaces[floor.surface].name == "floor");
    CHECK(floor.point.y == 0.0);
    CHECK(floor.normal.y == doctest::Approx(1).scale(0));
}

TEST_CASE("the Probe panel background path tracer refines to 0.1%, restarts and stops on request, and reports a back face") {
    const auto scene = std::make_shared<const Scene>(makeParallelPlates());
    const auto rays = std::make_shared<const RayCaster>(*scene);
    // The tracer runs at low priority: on a busy machine it crawls, so the wait fails only after
    // 120 s without a new batch, not after a fixed time.
    const auto waitUntilDone = [](const app::PathTracedReading& reading) {
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        app::PathTracedReading::State state = reading.state();
        std::uint64_t samples = 0;
        while (state.refining && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            state = reading.state();
            if (state.estimate && state.estimate->samples > samples) {
                samples = state.estimate->samples;
                deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
            }
        }
        return state;
    };
    app::PathTracedReading reading;
    CHECK_FALSE(reading.state().estimate);
    reading.start(scene, rays, {0.5, 1, 0.5}, {0, -1, 0});
    const app::PathTracedReading::State done = waitUntilDone(reading);
    REQUIRE(done.estimate);
    CHECK_FALSE(done.refining);
    CHECK(done.error.empty());
    CHECK(done.estimate->relativeStandardError() <= app::PathTracedReading::kTargetRelativeError);
    CHECK(app::PathTracedReading::converged(*done.estimate));
    const double F = 4 * pointToCornerRectangle(0.5, 0.5, 1.0);  // the built-in emitter's exitance is 1 W/m^2
    for (int band = 0; band < 3; ++band)
        checkWithin(done.estimate->irradiance.value()[band], done.estimate->irradianceStandardError[band], F, 4, 0.001);
    // Converged, it has stopped: no more paths arrive (its thread no longer competes with the view's).
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const app::PathTracedReading::State later = reading.state();
    REQUIRE(later.estimate);
    CHECK(later.estimate->samples == done.estimate->samples);
    CHECK_FALSE(later.refining);

    // A restart forgets the old estimate; stopping at once joins the worker and leaves nothing behind.
    reading.start(scene, rays, {0.25, 1, 0.75}, {0, -1, 0});
    reading.stop();
    CHECK_FALSE(reading.state().estimate);
    CHECK(reading.scene() == nullptr);

    // The receiver's back: the worker reports why there is no estimate.
    reading.start(scene, rays, {0.5, 1, 0.5}, {0, 1, 0});
    const app::PathTracedReading::State refused = waitUntilDone(reading);
    CHECK_FALSE(refused.estimate);
    CHECK(refused.error.find("degrees from the front of surface 'receiver'") != std::string::npos);
}

TEST_CASE("the Probe panel path tracer gives a first estimate at once, then refines only while no frames are drawn") {
    const auto scene = std::make_shared<const Scene>(makeParallelPlates());
    const auto rays = std::make_shared<const RayCaster>(*scene);
    app::PathTracedReading reading;
    reading.start(scene, rays, {0.5, 1, 0.5}, {0, -1, 0});
    // Frames every 10 ms, as a running solve draws them. Waits fail after 120 s without progress.
    const auto drawFramesUntil = [&](auto&& done) {
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        std::uint64_t samples = 0;
        for (;;) {
            reading.noteFrameDrawn();
            const app::PathTracedReading::State state = reading.state();
            if (done(state)) return state;
            if (state.estimate && state.estimate->samples > samples) {
                samples = state.estimate->samples;
                deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
            }
            REQUIRE(std::chrono::steady_clock::now() < deadline);
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    };
    const app::PathTracedReading::State paused =
        drawFramesUntil([](const app::PathTracedReading::State& state) { return state.waitingForStillView; });
    REQUIRE(paused.estimate);
    CHECK(paused.estimate->samples >= app::PathTracedReading::kMinimumSamples);
    CHECK(paused.refining);
    // Half a second more of frames: not one more path.
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    const app::PathTracedReading::State still =
        drawFramesUntil([&](const app::PathTracedReading::State&) { return std::chrono::steady_clock::now() >= until; });
    REQUIRE(still.estimate);
    CHECK(still.estimate->samples == paused.estimate->samples);
    CHECK(still.waitingForStillView);

    // The frames stop: it refines to its target and stops.
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    std::uint64_t samples = 0;
    app::PathTracedReading::State state = reading.state();
    while (state.refining) {
        REQUIRE(std::chrono::steady_clock::now() < deadline);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        state = reading.state();
        if (state.estimate && state.estimate->samples > samples) {
            samples = state.estimate->samples;
            deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        }
    }
    REQUIRE(state.estimate);
    CHECK(app::PathTracedReading::converged(*state.estimate));
    CHECK_FALSE(state.waitingForStillView);
    CHECK(state.estimate->samples > paused.estimate->samples);
}

TEST_CASE("the Probe panel path tracer's stopping rule: the target standard error, after a minimum of paths") {
    ReferenceEstimate e;
    e.irradiance = IrradianceRgb(Rgb(2.0, 1.0, 0.5));
    const auto withError = [&](double relative, std::uint64_t samples) {
        e.irradianceStandardError = Rgb(2.0, 1.0, 0.5) * relative;
        e.samples = samples;
        return app::PathTracedReading::converged(e);
    };
    const double target = app::PathTracedReading::kTargetRelativeError;
    const std::uint64_t enough = app::PathTracedReading::kMinimumSamples;
    CHECK(withError(0.5 * target, enough));
    CHECK_FALSE(withError(2 * target, 100 * enough));  // every band must be under the target
    CHECK_FALSE(withError(0.5 * target, enough - 1));   // a lucky early estimate is not trusted
    e.samples = 0;
    CHECK_FALSE(app::PathTracedReading::converged(e));  // no paths: an infinite error
}

TEST_CASE("radiant reference on the built-in parallel plates prints E = M F with its standard error, and bad input exits 2") {
    // The built-in: a black emitter [0,1]^2 at y = 0 (exitance 1) and a receiver of rho 0.5 at y = 1.
    const std::string output = "/tmp/radiant-test-reference-" + std::to_string(::getpid()) + ".json";
    const std::string command = std::string(RADIANT_BINARY) +
                                " reference parallel-plates --point 0.5,1,0.5 --normal 0,-1,0 --samples 200000 --json " +
                                output;
    REQUIRE(std::system(command.c_str()) == 0);
    std::ifstream in(output);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::remove(output.c_str());
    const double F = 4 * pointToCornerRectangle(0.5, 0.5, 1.0);
    CHECK(j["surface"] == "receiver");
    CHECK(j["samples"] == 200000);
    for (int band = 0; band < 3; ++band) {
        const double e = j["irradiance_W_m2"][band].get<double>();
        const double se = j["standard_error_W_m2"]["irradiance_W_m2"][band].get<double>();
        checkWithin(e, se, F, 4, 0.003);
        CHECK(j["radiosity_W_m2"][band].get<double>() == doctest::Approx(0.5 * e).scale(0).epsilon(1e-12));
    }
    const auto exitStatus = [](const std::string& arguments) {
        const int status = std::system((std::string(RADIANT_BINARY) + " reference " + arguments + " 2>/dev/null").c_str());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    CHECK(exitStatus("parallel-plates --point 0.5,0.5,0.5 --normal 0,-1,0") == 2);    // on no surface
    CHECK(exitStatus("parallel-plates --point 0.5,1,0.5 --normal 0,1,0") == 2);       // the receiver's back
    CHECK(exitStatus("parallel-plates --point 0.5,1 --normal 0,-1,0") == 2);          // two numbers
    CHECK(exitStatus("parallel-plates --point 0.5,1,0.5 --normal 0,-1,0 --seconds 0") == 2);
    CHECK(exitStatus("parallel-plates --point 0.5,1,0.5 --normal 0,-1,0 --samples 1") == 2);
}

} // TEST_SUITE
