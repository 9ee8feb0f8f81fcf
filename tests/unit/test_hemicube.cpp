// The hemicube (Cohen & Greenberg 1985) without GL: delta form factors against their closed forms
// and the hemisphere's integrals, and the hemicube's form factors (item buffer by ray casting)
// against docs/reference.md's closed forms for a differential area under a parallel rectangle:
//   F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
// and Omega = atan(ab / (h sqrt(a^2+b^2+h^2))) for the corner rectangle's solid angle.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>

#include "app/panels/HemisphereIntegralRun.h"
#include "app/panels/demos/LectureDemos.h"
#include "tests/support/Relative.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/hemicube/DeltaFormFactor.h"
#include "radiometry/hemicube/HemicubeGather.h"
#include "radiometry/hemicube/HemicubeLayout.h"
#include "radiometry/hemicube/HemicubeRayCast.h"
#include "radiometry/hemicube/HemisphereProjection.h"
#include "radiometry/mesh/PatchLocator.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {
using radiant::test::kPi;

/// Approx with a purely relative tolerance (doctest's default scale of 1 would make it absolute for small values).
using radiant::test::relativeTo;

double cornerFormFactor(double a, double b, double c) {
    const double A = a / c, B = b / c;
    return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
            B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
           (2 * kPi);
}
double cornerSolidAngle(double a, double b, double h) { return std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h))); }

double sum(const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); }

/// One rectangle [x0, x1] x [y0, y1] at height c facing down (-z) toward the origin.
Scene rectangleAbove(double x0, double x1, double y0, double y1, double c) {
    Scene scene;
    scene.name = "rectangle";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb(Rgb(0.0))});
    Face face;
    face.vertices = {{x0, y0, c}, {x0, y1, c}, {x1, y1, c}, {x1, y0, c}};  // clockwise from above: faces down
    face.updateGeometry();
    scene.surfaces.push_back({"rectangle", 0, {face}, "test"});
    return scene;
}

MeshingOptions meshing(double maxPatchArea) {
    MeshingOptions options;
    options.maxPatchArea = maxPatchArea;
    return options;
}

struct CastReading {
    HemicubeGatherResult result;
    std::vector<std::uint32_t> items;
};

CastReading castAndGather(const Scene& scene, const PatchMesh& mesh, int resolution, const glm::dvec3& x,
                          const glm::dvec3& n, std::span<const Rgb> radiosity = {}) {
    const HemicubeLayout layout(resolution);
    const RayCaster rays(scene);
    const PatchLocator locator(mesh);
    CastReading reading;
    reading.items = castHemicube(layout, rays, locator, x, n);
    reading.result = gatherHemicube(layout, reading.items, mesh, scene.surfaces.size(), radiosity);
    return reading;
}

} // namespace

TEST_SUITE("hemicube") {

TEST_CASE("delta form factors are the closed forms of Cohen & Greenberg") {
    const double dA = 0.01;
    for (const double x : {0.0, 0.3, -0.9})
        for (const double y : {0.0, 0.55, -0.2}) {
            const double s = x * x + y * y + 1;
            CHECK(topFaceDeltaFormFactor(x, y, dA) == relativeTo(dA / (kPi * s * s), 1e-14));
            CHECK(deltaFormFactor({x, y, 1.0}, dA) == relativeTo(topFaceDeltaFormFactor(x, y, dA), 1e-14));
        }
    for (const double y : {0.0, 0.4, -0.95})
        for (const double z : {0.05, 0.5, 0.99}) {
            const double s = y * y + z * z + 1;
            CHECK(sideFaceDeltaFormFactor(y, z, dA) == relativeTo(z * dA / (kPi * s * s), 1e-14));
            // The same pixel on the +x face, seen as a direction (1, y, z).
            CHECK(deltaFormFactor({1.0, y, z}, dA) == relativeTo(sideFaceDeltaFormFactor(y, z, dA), 1e-14));
        }
}

TEST_CASE("delta form factors sum to 1 and solid angles to 2 pi, converging with resolution") {
    const HemicubeLayout at128(128);
    CHECK(std::abs(sum(at128.deltaFormFactors()) - 1.0) < 1e-3);
    CHECK(std::abs(sum(at128.solidAngles()) - 2 * kPi) < 2 * kPi * 1e-3);
    double previous = 1;
    for (const int resolution : {8, 16, 32, 64, 128, 256}) {
        const double error = std::abs(sum(HemicubeLayout(resolution).deltaFormFactors()) - 1.0);
        INFO("resolution ", resolution, ": |sum - 1| = ", error);
        CHECK(error < previous / 2);  // the midpoint rule: about 4x smaller per doubling
        previous = error;
    }
}

TEST_CASE("every pixel's direction looks up to the same pixel") {
    const HemicubeLayout layout(24);
    for (int row = 0; row < layout.height(); ++row)
        for (int column = 0; column < layout.width(); ++column)
            REQUIRE(layout.pixelIndexOf(layout.pixelDirection(column, row)) ==
                    static_cast<std::size_t>(row * layout.width() + column));
    CHECK_THROWS_AS(HemicubeLayout(31), RadiantError);
    CHECK_THROWS_AS(HemicubeLayout(0), RadiantError);
}

TEST_CASE("hemicube form factor of a rectangle over a corner matches the closed form") {
    // Several shapes and heights; the error is the pixel-edge aliasing along the rectangle's outline.
    struct Case { double a, b, c; };
    for (const Case k : {Case{1.0, 1.0, 1.0}, Case{0.5, 2.0, 1.0}, Case{0.3, 0.4, 0.25}, Case{2.0, 3.0, 0.7}}) {
        const Scene scene = rectangleAbove(0, k.a, 0, k.b, k.c);
        const PatchMesh mesh = meshScene(scene, meshing(k.a * k.b / 4));
        const CastReading reading = castAndGather(scene, mesh, 256, {0, 0, 0}, {0, 0, 1});
        const double exact = cornerFormFactor(k.a, k.b, k.c);
        INFO("a = ", k.a, ", b = ", k.b, ", c = ", k.c, ": hemicube F = ", reading.result.surfaces[0].formFactor,
             ", exact ", exact);
        CHECK(reading.result.surfaces[0].formFactor == relativeTo(exact, 0.01));
        CHECK(reading.result.surfaces[0].solidAngle.value() ==
              relativeTo(cornerSolidAngle(k.a, k.b, k.c), 0.01));
    }
}

TEST_CASE("a rectangle seen from its back blocks but sends nothing") {
    Scene scene = rectangleAbove(-0.5, 0.5, -0.5, 0.5, 1.0);
    for (Face& face : scene.surfaces[0].faces) {
        std::reverse(face.vertices.begin(), face.vertices.end());  // now faces up, away from the point
        face.updateGeometry();
    }
    const PatchMesh mesh = meshScene(scene, meshing(1.0));
    const CastReading reading = castAndGather(scene, mesh, 128, {0, 0, 0}, {0, 0, 1});
    CHECK(reading.result.surfaces[0].formFactor == 0.0);
    CHECK(reading.result.backFaceFormFactor == relativeTo(4 * cornerFormFactor(0.5, 0.5, 1.0), 0.01));
}

TEST_CASE("in the unit cube the floor's centre sees the ceiling's closed form, and all walls sum to 1") {
    const Scene cube = makeUnitCube();
    const PatchMesh mesh = meshScene(cube, meshing(0.04));
    const std::size_t ceiling = cube.findSurface("ceiling");
    REQUIRE(ceiling != Scene::npos);
    // Radiosity 1 W/m^2 on the ceiling only: E = F(dx -> ceiling) x 1 W/m^2.
    std::vector<Rgb> radiosity(mesh.size(), Rgb(0.0));
    for (std::size_t p = 0; p < mesh.size(); ++p)
        if (mesh.patches[p].surface == ceiling) radiosity[p] = Rgb(1.0, 2.0, 0.5);
    const CastReading reading = castAndGather(cube, mesh, 256, {0.5, 0.0, 0.5}, {0, 1, 0}, radiosity);
    const double exact = 4 * cornerFormFactor(0.5, 0.5, 1.0);
    CHECK(reading.result.surfaces[ceiling].formFactor == relativeTo(exact, 0.005));
    double total = 0;
    for (const HemicubeSurfaceReading& s : reading.result.surfaces) total += s.formFactor;
    CHECK(total == relativeTo(sum(HemicubeLayout(256).deltaFormFactors()), 1e-9));  // closed: no sky
    CHECK(reading.result.openFormFactor == 0.0);
    CHECK(reading.result.irradiance.value().x == relativeTo(exact, 0.005));
    CHECK(reading.result.irradiance.value().y == relativeTo(2 * exact, 0.005));
    CHECK(reading.result.irradiance.value().z == relativeTo(0.5 * exact, 0.005));
}

TEST_CASE("projections map the disk to the hemisphere and back") {
    for (const HemisphereProjection projection :
         {HemisphereProjection::Nusselt, HemisphereProjection::Equidistant, HemisphereProjection::Equisolid})
        for (const glm::dvec2 p : {glm::dvec2(0.0, 0.0), glm::dvec2(0.3, -0.4), glm::dvec2(-0.7, 0.69)}) {
            const std::optional<glm::dvec3> d = directionAtDiskPoint(projection, p);
            REQUIRE(d.has_value());
            CHECK(glm::length(*d) == relativeTo(1.0, 1e-12));
            const glm::dvec2 back = diskPointOfDirection(projection, *d);
            // Disk coordinates lie in [-1, 1], and (0, 0) is among them: an absolute tolerance.
            CHECK(std::abs(back.x - p.x) < 1e-9);
            CHECK(std::abs(back.y - p.y) < 1e-9);
        }
    CHECK_FALSE(directionAtDiskPoint(HemisphereProjection::Nusselt, {0.8, 0.8}).has_value());
    // The rim is the horizon in every projection.
    CHECK(std::abs(directionAtDiskPoint(HemisphereProjection::Equidistant, {1.0, 0.0})->z) < 1e-12);
    CHECK(std::abs(directionAtDiskPoint(HemisphereProjection::Equisolid, {0.0, 1.0})->z) < 1e-12);
}

TEST_CASE("Nusselt view: covered disk fraction is the form factor, and equisolid: solid angle over 2 pi") {
    struct Case { double half, c; };
    for (const Case k : {Case{0.5, 1.0}, Case{1.0, 0.5}, Case{0.2, 0.6}}) {
        const Scene scene = rectangleAbove(-k.half, k.half, -k.half, k.half, k.c);
        const PatchMesh mesh = meshScene(scene, meshing(1.0));
        // The share is quantised twice (hemicube pixels, then disk pixels): about one pixel along the
        // outline, 1.6 % for the smallest square at 256 x 400, under 1 % at 512 x 800.
        const HemicubeLayout layout(512);
        const CastReading reading = castAndGather(scene, mesh, 512, {0, 0, 0}, {0, 0, 1});
        const auto seesSquare = [](std::uint32_t item) { return hemicubeItemIsFront(item); };
        const double nusselt = diskCoverage(HemisphereViewMap(layout, HemisphereProjection::Nusselt, 800),
                                            reading.items, seesSquare);
        const double equisolid = diskCoverage(HemisphereViewMap(layout, HemisphereProjection::Equisolid, 800),
                                              reading.items, seesSquare);
        INFO("square of half-width ", k.half, " at height ", k.c);
        CHECK(nusselt == relativeTo(4 * cornerFormFactor(k.half, k.half, k.c), 0.01));
        CHECK(equisolid == relativeTo(4 * cornerSolidAngle(k.half, k.half, k.c) / (2 * kPi), 0.01));
    }
}

TEST_CASE("Monte Carlo error of the integrals shrinks as 1/sqrt(N), cosine sampling is exact for cos theta") {
    using app::HemisphereIntegralRun;
    using app::IntegralMethod;
    using app::IntegralSettings;
    // Root-mean-square error over 40 seeds at N = 100 and N = 10000: 1/sqrt(N) predicts a ratio of 10.
    const auto rmsError = [](std::size_t n) {
        double squares = 0;
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            HemisphereIntegralRun run([](const glm::dvec3& d) { return d.z; }, kPi,
                                      IntegralSettings{IntegralMethod::UniformMonteCarlo, 16, n, seed});
            run.step(n);
            squares += std::pow(run.estimate().value - kPi, 2);
        }
        return std::sqrt(squares / 40);
    };
    const double ratio = rmsError(100) / rmsError(10000);
    INFO("rms error ratio N = 100 vs 10000: ", ratio);
    CHECK(ratio > 6.0);
    CHECK(ratio < 16.0);

    HemisphereIntegralRun cosine([](const glm::dvec3& d) { return d.z; }, kPi,
                                 IntegralSettings{IntegralMethod::CosineMonteCarlo, 16, 50, 7});
    cosine.step(50);
    CHECK(cosine.estimate().value == relativeTo(kPi, 1e-12));  // f / pdf = pi for every sample

    HemisphereIntegralRun riemann([](const glm::dvec3&) { return 1.0; }, 2 * kPi,
                                  IntegralSettings{IntegralMethod::Riemann, 32, 0, 1});
    CHECK_FALSE(riemann.step(1u << 20));
    REQUIRE(riemann.errorHistory().size() == 1);
    // Midpoint rule in theta: h sum_i sin((i + 1/2) h) = h sin^2(pi / 4) / sin(h / 2), so the sum is
    // 2 pi (h / 2) / sin(h / 2) = 2 pi (1 + h^2 / 24 + ...): the O(h^2) error, from above.
    const double h = kPi / 2 / 32;
    CHECK(riemann.estimate().value == relativeTo(2 * kPi * (h / 2) / std::sin(h / 2), 1e-12));
    // The history records the Monte Carlo run at increasing counts, ending at the last sample.
    HemisphereIntegralRun uniform([](const glm::dvec3&) { return 1.0; }, 2 * kPi,
                                  IntegralSettings{IntegralMethod::UniformMonteCarlo, 16, 1000, 3});
    uniform.step(1000);
    CHECK(uniform.errorHistory().back().samples == 1000);
    CHECK(uniform.errorHistory().size() > 20);
    CHECK(uniform.estimate().value == relativeTo(2 * kPi, 1e-12));  // constant f / uniform pdf
}

TEST_CASE("lecture demos' numbers match the closed forms of docs/reference.md") {
    using namespace app;
    // Point source: E = P cos(theta) / (4 pi r^2), r^2 = h^2 + x^2, cos = h / r.
    for (const double h : {0.5, 1.0, 3.0})
        for (const double x : {0.0, 0.7, -2.0}) {
            const PointSourceNumbers n = pointSourceNumbers({60.0, h, x});
            const double r2 = h * h + x * x;
            CHECK(n.irradiance.value() == relativeTo(60.0 * (h / std::sqrt(r2)) / (4 * kPi * r2), 1e-12));
        }
    // Diffuse emitter: P = pi L A, B = pi L.
    const DiffuseEmitterNumbers emitter = diffuseEmitterNumbers({250.0, 0.4});
    CHECK(emitter.power.value() == relativeTo(kPi * 250.0 * 0.4, 1e-12));
    CHECK(emitter.exitance.value() == relativeTo(kPi * 250.0, 1e-12));
    // Sun: L = 3.91e26 / (pi 6.07e18) = 2.05e7; lecture 1373.5 W and 598.6 W; geometry 6.78e-5 sr, 1390 W/m^2.
    const SunNumbers sun = sunNumbers();
    CHECK(sun.radiance.value() == relativeTo(3.91e26 / (kPi * 6.07e18), 1e-12));
    CHECK(sun.earth.lectureIrradiance.value() == relativeTo(1373.5, 0.005));
    CHECK(sun.mars.lectureIrradiance.value() == relativeTo(598.6, 0.005));
    CHECK(sun.earth.exactSolidAngle.value() == relativeTo(6.78e-5, 0.005));
    CHECK(sun.earth.irradiance.value() == relativeTo(1390, 0.005));
    CHECK(sun.earth.irradiance.value() / sun.earth.lectureIrradiance.value() == relativeTo(1.012, 0.005));
    // Square of side s at distance R: 4 atan((s/2)^2 / (R sqrt(s^2/2 + R^2))) against s^2 / R^2.
    for (const double R : {0.2, 1.0, 10.0}) {
        const SquareSolidAngleNumbers n = squareSolidAngleNumbers({1.0, R});
        CHECK(n.exact.value() == relativeTo(4 * std::atan(0.25 / (R * std::sqrt(0.5 + R * R))), 1e-12));
        CHECK(n.smallArea.value() == relativeTo(1.0 / (R * R), 1e-12));
    }
    CHECK(squareSolidAngleNumbers({1.0, 10.0}).relativeError < 0.01);  // far: A / R^2 is good
    CHECK(squareSolidAngleNumbers({1.0, 0.2}).relativeError > 1.0);    // close: it overshoots
    // Regular solids: 4 pi / n both from the formula and from one face's vertices.
    for (const int faces : {4, 6, 8, 12, 20}) {
        const RegularSolidNumbers n = regularSolidNumbers(faces);
        CHECK(n.perFace.value() == relativeTo(4 * kPi / faces, 1e-12));
        CHECK(n.polygonRoute.value() == relativeTo(4 * kPi / faces, 1e-9));
    }
    CHECK(regularSolidNumbers(12).perFace.value() == relativeTo(1.047, 1e-3));
    // Radiance vs irradiance: E = L omega cos(theta), L unchanged.
    for (const double tilt : {0.0, 30.0, 60.0, 89.0}) {
        const RadianceIrradianceNumbers n = radianceIrradianceNumbers({1000.0, 2e-3, tilt});
        CHECK(n.radiance.value() == 1000.0);
        CHECK(n.irradiance.value() == relativeTo(1000.0 * 2e-3 * std::cos(tilt * kPi / 180), 1e-12));
    }
}

} // TEST_SUITE
