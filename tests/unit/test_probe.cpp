// ctest-labels: threads
// The point probe on scenes built in code, against closed forms (docs/reference.md): the differential
// area to a parallel rectangle with its corner on the normal, F = 1/(2 pi) [A/sqrt(1+A^2)
// atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))], and the corner-rectangle solid angle
// atan(ab / (h sqrt(a^2+b^2+h^2))). Any rectangle over a point splits into signed corner rectangles.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <unistd.h>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/panels/ProbePanel.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/probe/RadiosityInterpolation.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/sources/PunctualLight.h"
#include "tests/support/CatalogViewFactors.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {
using radiant::test::kPi;

using test::cornerRectangleSolidAngle;
using test::overRectangle;
using test::pointToCornerRectangle;

Face rectangleFace(std::array<glm::dvec3, 4> corners) {
    Face face;
    face.vertices.assign(corners.begin(), corners.end());
    face.updateGeometry();
    return face;
}

/// A unit-square "receiver" at z = 0 facing +z, centred on the origin; a unit-square "emitter" at
/// z = h facing -z (exitance 1, black); optionally a black "blocker" at z = h / 2 covering
/// x <= blockerEdge (facing -z).
Scene parallelSquares(double h, std::optional<double> blockerEdge = std::nullopt) {
    Scene scene;
    scene.name = "parallel squares";
    scene.materials = {{"receiver", Rgb(0.5), ExitanceRgb{}}, {"emitter", Rgb(0.0), ExitanceRgb(Rgb(1.0))},
                       {"blocker", Rgb(0.0), ExitanceRgb{}}};
    scene.surfaces.push_back(
        {"receiver", 0, {rectangleFace({{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}}})}, "test"});
    scene.surfaces.push_back(
        {"emitter", 1, {rectangleFace({{{-0.5, -0.5, h}, {-0.5, 0.5, h}, {0.5, 0.5, h}, {0.5, -0.5, h}}})}, "test"});
    if (blockerEdge) {
        const double e = *blockerEdge, z = h / 2;
        scene.surfaces.push_back(
            {"blocker", 2, {rectangleFace({{{-1, -1, z}, {-1, 1, z}, {e, 1, z}, {e, -1, z}}})}, "test"});
    }
    return scene;
}

MeshingOptions probeMeshing(double maxPatchArea) {
    MeshingOptions options;
    options.maxPatchArea = maxPatchArea;
    return options;
}

/// B = 1 on the emitter's patches, 0 elsewhere.
std::vector<Rgb> emitterOnly(const PatchMesh& mesh, std::uint32_t emitter) {
    std::vector<Rgb> b(mesh.size(), Rgb(0.0));
    for (std::size_t p = 0; p < mesh.size(); ++p)
        if (mesh.patches[p].surface == emitter) b[p] = Rgb(1.0);
    return b;
}
} // namespace

TEST_SUITE("probe") {

TEST_CASE("on parallel squares the probe's F, solid angle and E match the corner-rectangle closed forms") {
    for (double h : {0.5, 1.0, 2.0})
        for (glm::dvec3 x : {glm::dvec3(0, 0, 0), glm::dvec3(0.2, -0.1, 0), glm::dvec3(-0.45, 0.3, 0)}) {
            CAPTURE(h);
            CAPTURE(x.x);
            CAPTURE(x.y);
            const Scene scene = parallelSquares(h);
            REQUIRE(scene.surfaces[1].faces[0].normal.z == doctest::Approx(-1.0).scale(0));
            const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
            const RayCaster rays(scene);
            const Probe probe(scene, mesh, &rays);
            const ProbeReading r = probe.measure(x, {0, 0, 1}, emitterOnly(mesh, 1), std::size_t{1});
            const double expectedF = overRectangle(pointToCornerRectangle, -0.5 - x.x, 0.5 - x.x, -0.5 - x.y,
                                                          0.5 - x.y, h);
            const double expectedOmega = overRectangle(cornerRectangleSolidAngle, -0.5 - x.x, 0.5 - x.x, -0.5 - x.y,
                                                              0.5 - x.y, h);
            if (x == glm::dvec3(0.0)) {  // the centre: four equal 0.5 x 0.5 corner rectangles
                CHECK(expectedF == doctest::Approx(4 * pointToCornerRectangle(0.5, 0.5, h)).epsilon(1e-14).scale(0));
                CHECK(expectedOmega == doctest::Approx(4 * cornerRectangleSolidAngle(0.5, 0.5, h)).epsilon(1e-14).scale(0));
            }
            REQUIRE(r.target);
            CHECK(r.target->name == "emitter");
            CHECK(std::abs(r.target->formFactor - expectedF) < 1e-6);
            CHECK(std::abs(r.target->projectedSolidAngle.value() - kPi * expectedF) < 1e-6);
            CHECK(std::abs(r.target->solidAngle.value() - expectedOmega) < 1e-6);
            for (int band = 0; band < 3; ++band) CHECK(std::abs(r.irradiance.value()[band] - expectedF) < 1e-6);
            CHECK(r.interpolatedRadiosity.value().x == 0.0);  // the receiver's own patches are dark
            // B at the point is M + rho E with the receiver's rho = 0.5 and no emission of its own.
            for (int band = 0; band < 3; ++band)
                CHECK(r.radiosity.value()[band] == doctest::Approx(0.5 * r.irradiance.value()[band]).epsilon(1e-12).scale(0));
            CHECK(r.radiance.value().x == doctest::Approx(r.radiosity.value().x / kPi).epsilon(1e-12).scale(0));
            CHECK(scene.surfaces[r.at.surface].name == "receiver");
        }
}

TEST_CASE("the gather reads a patch's slope: a linear radiosity over a near square matches its closed form") {
    // The emitter 2 cm over the receiver carries B(y) = 1 + 1.8 y_x (0.1 to 1.9 W/m^2 across it) on
    // 10 cm patches, five times its height: the kernel falls steeply across each patch. With u = y_x - x_x,
    // E(x) = B(x_x) F + 1.8 M, where M = int u h^2 / (pi (u^2 + v^2 + h^2)^2) dA integrates in closed
    // form (in u: -1 / (2 (u^2 + c^2)); then in v: atan), over the rectangle [u0, u1] x [v0, v1]:
    // M = h^2 / (2 pi) [g(u0) - g(u1)], g(u) = (atan(v1 / a) - atan(v0 / a)) / a, a = sqrt(u^2 + h^2).
    // A constant per patch reads E 1.7-3.8% off at these points (it weighs each patch's far side as
    // much as its near side); with the slope fitted to the neighbours 0.05-0.32% (the kernel's
    // moment is estimated from the gather's 4 x 4 ray points). The last point lies under the
    // emitter's edge row: limited to its neighbours' range there too, that row's slope is flattened
    // and the reading is -1.6% off; the edge's corners are bounded only by positivity (-0.05%).
    const double h = 0.02, slope = 1.8;
    const Scene scene = parallelSquares(h);
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
    const RayCaster rays(scene);
    std::vector<Rgb> b(mesh.size(), Rgb(0.0));
    for (std::size_t p = 0; p < mesh.size(); ++p)
        if (mesh.patches[p].surface == 1) b[p] = Rgb(1 + slope * mesh.patches[p].centroid.x);  // exact patch means
    const auto g = [h](double u, double v0, double v1) {
        const double a = std::sqrt(u * u + h * h);
        return (std::atan(v1 / a) - std::atan(v0 / a)) / a;
    };
    ProbeOptions constant;
    constant.gatherSlopes = false;
    const Probe probe(scene, mesh, &rays), probeConstant(scene, mesh, &rays, constant);
    double worstBefore = 0;
    for (glm::dvec3 x : {glm::dvec3(0.03, 0.01, 0), glm::dvec3(-0.12, 0.07, 0), glm::dvec3(0.21, -0.26, 0),
                         glm::dvec3(0.47, 0.12, 0)}) {
        CAPTURE(x.x);
        CAPTURE(x.y);
        const double u0 = -0.5 - x.x, u1 = 0.5 - x.x, v0 = -0.5 - x.y, v1 = 0.5 - x.y;
        const double f = overRectangle(pointToCornerRectangle, u0, u1, v0, v1, h);
        const double m = h * h / (2 * kPi) * (g(u0, v0, v1) - g(u1, v0, v1));
        const double expected = (1 + slope * x.x) * f + slope * m;
        const double before = probeConstant.measure(x, {0, 0, 1}, b).irradiance.value().x;
        const double after = probe.measure(x, {0, 0, 1}, b).irradiance.value().x;
        worstBefore = std::max(worstBefore, std::abs(before / expected - 1));
        CHECK(std::abs(after / expected - 1) < 0.005);
    }
    CHECK(worstBefore > 0.01);  // the constant reading is measurably off: the case tests the slope
}

TEST_CASE("the gather reads a hard shadow's edge across a patch: a plate's shadow on the floor matches its closed form") {
    // A sun (a directional light, 1 W/m^2 facing it) slants down toward -x; a black plate 10 cm over
    // a 1 m floor (rho 0.5, 10 cm patches) covers x <= 0, so the floor is lit exactly where
    // x > -0.02 and the edge crosses the patch row [-0.1, 0] at a fifth of its width. Each patch is
    // given its exact mean, rho E0 times its lit fraction. From the plate's underside a point sees
    // E = rho E0 F(x -> the lit rectangle [-0.02, 0.5] x [-0.5, 0.5]), the corner-rectangle closed form.
    // Read as mean plus neighbours' slope, the edge patch and its lit neighbour (tilted by the edge
    // patch's low mean) leave +2.8%, -2.2% and +11.5% at these points however many gather points are
    // drawn. With the direct light read at each gather point the reading converges to the closed form
    // (16 x 16 points: within 0.22%); at the default 4 x 4 a hard edge is sampled coarsely (-1.2%,
    // +0.8%, -4.3%), still closer than the mean and slope at every point.
    const double h = 0.1, rho = 0.5;
    Scene scene;
    scene.name = "sunlit floor under a plate";
    scene.materials = {{"floor", Rgb(rho), ExitanceRgb{}}, {"plate", Rgb(0.0), ExitanceRgb{}}};
    scene.surfaces.push_back(
        {"floor", 0, {rectangleFace({{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}}})}, "test"});
    scene.surfaces.push_back(
        {"plate", 1, {rectangleFace({{{-0.6, -0.6, h}, {-0.6, 0.6, h}, {0, 0.6, h}, {0, -0.6, h}}})}, "test"});
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.2, 0, -1));
    sun.normalIrradiance = IrradianceRgb(Rgb(1.0));
    scene.lights.push_back(sun);
    const double e0 = -sun.direction.z;  // E on the lit floor, W/m^2
    const double edge = -0.2 * h;        // the shadow's edge: x = 0 at the plate, moved 0.2 h along -x
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
    const RayCaster rays(scene);
    std::vector<Rgb> b(mesh.size(), Rgb(0.0));
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        if (mesh.patches[p].surface != 0) continue;
        double x0 = 1, x1 = -1;
        const PatchPolygon polygon = mesh.polygon(p);  // corners() views the polygon: keep it alive
        for (const glm::dvec3& v : polygon.corners()) {
            x0 = std::min(x0, v.x);
            x1 = std::max(x1, v.x);
        }
        b[p] = Rgb(rho * e0 * std::clamp((x1 - std::max(x0, edge)) / (x1 - x0), 0.0, 1.0));
    }
    ProbeOptions meanPlusSlope, fine, fineMeanPlusSlope;
    meanPlusSlope.gatherDirect = fineMeanPlusSlope.gatherDirect = false;
    fine.gatherRaysPerSide = fineMeanPlusSlope.gatherRaysPerSide = 16;
    const Probe probe(scene, mesh, &rays), probeMeanPlusSlope(scene, mesh, &rays, meanPlusSlope);
    const Probe probeFine(scene, mesh, &rays, fine), probeFineMeanPlusSlope(scene, mesh, &rays, fineMeanPlusSlope);
    double worstMeanPlusSlope = 0;
    for (const glm::dvec3 x : {glm::dvec3(-0.05, 0.02, h), glm::dvec3(-0.01, -0.13, h), glm::dvec3(-0.13, 0.21, h)}) {
        CAPTURE(x.x);
        CAPTURE(x.y);
        const double expected = rho * e0 * overRectangle(pointToCornerRectangle, edge - x.x, 0.5 - x.x, -0.5 - x.y, 0.5 - x.y, h);
        const auto error = [&](const Probe& on) { return on.measure(x, {0, 0, -1}, b).irradiance.value().x / expected - 1; };
        const double direct = error(probe), meanAndSlope = error(probeMeanPlusSlope);
        const double fineDirect = error(probeFine), fineMeanAndSlope = error(probeFineMeanPlusSlope);
        CAPTURE(direct);
        CAPTURE(meanAndSlope);
        CAPTURE(fineDirect);
        CAPTURE(fineMeanAndSlope);
        CHECK(std::abs(fineDirect) < 0.005);
        CHECK(std::abs(direct) < std::abs(meanAndSlope));
        CHECK(std::abs(direct) < 0.05);
        worstMeanPlusSlope = std::max(worstMeanPlusSlope, std::abs(fineMeanAndSlope));
    }
    CHECK(worstMeanPlusSlope > 0.02);  // the mean-plus-slope reading is measurably off: the case tests the direct light
}

TEST_CASE("a closed block counts its silhouette once, and a target seen from behind has a projected solid angle") {
    // A unit-square "receiver" at z = 0 facing +z; a closed cube [-0.5, 0.5]^2 x [h, h + 1] with
    // outward faces; a "panel" square at z = h facing +z, which the origin sees from behind.
    const double h = 1.0;
    Scene scene;
    scene.name = "block over a point";
    scene.materials = {{"grey", Rgb(0.5), ExitanceRgb{}}};
    scene.surfaces.push_back(
        {"receiver", 0, {rectangleFace({{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}}})}, "test"});
    const double a = 0.5, z0 = h, z1 = h + 1;
    Surface block{"block", 0, {}, "test"};
    block.faces.push_back(rectangleFace({{{-a, -a, z0}, {-a, a, z0}, {a, a, z0}, {a, -a, z0}}}));  // bottom, -z
    block.faces.push_back(rectangleFace({{{-a, -a, z1}, {a, -a, z1}, {a, a, z1}, {-a, a, z1}}}));  // top, +z
    block.faces.push_back(rectangleFace({{{a, -a, z0}, {a, a, z0}, {a, a, z1}, {a, -a, z1}}}));    // +x
    block.faces.push_back(rectangleFace({{{-a, -a, z0}, {-a, -a, z1}, {-a, a, z1}, {-a, a, z0}}}));  // -x
    block.faces.push_back(rectangleFace({{{-a, a, z0}, {-a, a, z1}, {a, a, z1}, {a, a, z0}}}));    // +y
    block.faces.push_back(rectangleFace({{{-a, -a, z0}, {a, -a, z0}, {a, -a, z1}, {-a, -a, z1}}}));  // -y
    scene.surfaces.push_back(block);
    for (const Face& face : scene.surfaces[1].faces)  // outward: away from the cube's centre
        REQUIRE(glm::dot(face.normal, face.vertices[0] - glm::dvec3(0, 0, h + a)) > 0);
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.02));
    const RayCaster rays(scene);
    const Probe probe(scene, mesh, &rays);
    const std::vector<Rgb> dark(mesh.size(), Rgb(0.0));
    const double silhouetteOmega = 4 * cornerRectangleSolidAngle(a, a, h);
    const double silhouetteF = 4 * pointToCornerRectangle(a, a, h);
    // From the origin the block's bottom face is its whole silhouette.
    const ProbeReading r = probe.measure(glm::dvec3(0.0), glm::dvec3(0, 0, 1), dark, std::size_t{1});
    REQUIRE(r.target);
    CHECK(r.target->unoccludedSolidAngle.value() == doctest::Approx(silhouetteOmega).epsilon(1e-6).scale(0));
    CHECK(r.target->unoccludedFormFactor == doctest::Approx(silhouetteF).epsilon(1e-6).scale(0));
    CHECK(r.target->solidAngle.value() == doctest::Approx(silhouetteOmega).epsilon(1e-3).scale(0));
    CHECK(r.target->projectedSolidAngle.value() == doctest::Approx(kPi * silhouetteF).epsilon(1e-3).scale(0));

    // The same square seen from behind: light cannot leave its back, so F = 0, but the point still
    // sees it: solid angle and projected solid angle as for its front.
    Scene behind = parallelSquares(h);
    behind.surfaces[1].name = "panel";
    behind.surfaces[1].faces[0] = rectangleFace({{{-a, -a, h}, {a, -a, h}, {a, a, h}, {-a, a, h}}});  // faces +z
    const PatchMesh behindMesh = meshScene(behind, probeMeshing(0.02));
    const RayCaster behindRays(behind);
    const Probe behindProbe(behind, behindMesh, &behindRays);
    const ProbeReading b =
        behindProbe.measure(glm::dvec3(0.0), glm::dvec3(0, 0, 1), std::vector<Rgb>(behindMesh.size(), Rgb(0.0)),
                            std::size_t{1});
    REQUIRE(b.target);
    CHECK(b.target->formFactor == 0.0);
    CHECK(b.target->unoccludedFormFactor == 0.0);
    CHECK(b.target->solidAngle.value() == doctest::Approx(silhouetteOmega).epsilon(1e-6).scale(0));
    CHECK(b.target->projectedSolidAngle.value() == doctest::Approx(kPi * silhouetteF).epsilon(1e-6).scale(0));
}

TEST_CASE("a blocker halfway up hides the part of the emitter behind it") {
    // Seen from the origin, a blocker edge at x = e, height h/2 projects to x = 2e on the emitter:
    // the visible part is [2e, 0.5] x [-0.5, 0.5].
    for (double h : {1.0, 2.0})
        for (double e : {0.0, 0.125, -0.1}) {
            CAPTURE(h);
            CAPTURE(e);
            const Scene scene = parallelSquares(h, e);
            const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
            const RayCaster rays(scene);
            const Probe probe(scene, mesh, &rays);
            const ProbeReading r = probe.measure(glm::dvec3(0.0), glm::dvec3(0, 0, 1), emitterOnly(mesh, 1), std::size_t{1});
            const double visibleF = overRectangle(pointToCornerRectangle, 2 * e, 0.5, -0.5, 0.5, h);
            const double visibleOmega = overRectangle(cornerRectangleSolidAngle, 2 * e, 0.5, -0.5, 0.5, h);
            const double fullF = 4 * pointToCornerRectangle(0.5, 0.5, h);
            REQUIRE(r.target);
            CHECK(r.target->unoccludedFormFactor == doctest::Approx(fullF).epsilon(1e-9).scale(0));
            CHECK(r.target->formFactor == doctest::Approx(visibleF).epsilon(5e-4).scale(0));
            CHECK(r.target->solidAngle.value() == doctest::Approx(visibleOmega).epsilon(5e-4).scale(0));
            CHECK(r.irradiance.value().x == doctest::Approx(visibleF).epsilon(1e-3).scale(0));
        }
}

TEST_CASE("a patch seen only in part is sampled again: a blocker's edge across the emitter's patches matches its closed form") {
    // As above, but the blocker's edge seen from the point falls inside a patch of the emitter and
    // inside one of its 4 x 4 gather strata, where jittered rays read the patch's visible share by
    // chance, or leaves a sliver of a patch (1.6 and 8.4 mm of its 10 cm) that all of them may miss.
    // The part seen is [2e, 0.5] x [-0.5, 0.5] from the origin, [2e - x, 0.5] from a point x off it.
    // 4 x 4 rays alone: -0.76% to +1.05%; sampled again (the patches read in part, and those whose
    // share differs from a neighbour's): within 0.06%.
    double worstCoarse = 0;
    for (const double e : {0.1105, -0.0337, 0.0613})
        for (const glm::dvec3 x : {glm::dvec3(0.0), glm::dvec3(0.031, -0.017, 0)}) {
            CAPTURE(e);
            CAPTURE(x.x);
            const double h = 1.0;
            const Scene scene = parallelSquares(h, e);
            const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
            const RayCaster rays(scene);
            ProbeOptions coarse;
            coarse.partialRaysPerSide = 0;
            const Probe probe(scene, mesh, &rays), probeCoarse(scene, mesh, &rays, coarse);
            // The edge at x = e, height h/2, seen from x, lands on the emitter at x + 2 (e - x).
            const double seenFrom = x.x + 2 * (e - x.x);
            const double expected = overRectangle(pointToCornerRectangle, seenFrom - x.x, 0.5 - x.x, -0.5 - x.y, 0.5 - x.y, h);
            const double fine = probe.measure(x, {0, 0, 1}, emitterOnly(mesh, 1)).irradiance.value().x / expected - 1;
            const double coarseError = probeCoarse.measure(x, {0, 0, 1}, emitterOnly(mesh, 1)).irradiance.value().x / expected - 1;
            CAPTURE(fine);
            CAPTURE(coarseError);
            CHECK(std::abs(fine) < 0.002);
            worstCoarse = std::max(worstCoarse, std::abs(coarseError));
        }
    CHECK(worstCoarse > 0.005);  // the coarse rays alone are measurably off: the case tests the second sampling
}

TEST_CASE("radiosity interpolation reproduces a linear field inside a surface") {
    const Scene scene = parallelSquares(1.0);
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.01));
    const auto field = [](const glm::dvec3& p) { return Rgb(1 + 2 * p.x, 3 - p.y, 0.5 + p.x + p.y); };
    std::vector<Rgb> b(mesh.size(), Rgb(0.0));
    for (std::size_t p = 0; p < mesh.size(); ++p)
        if (mesh.patches[p].surface == 0) b[p] = field(mesh.patches[p].centroid);
    const Probe probe(scene, mesh, nullptr);
    // Away from the border ring of patches, nodal averaging of a linear field is exact, and so is
    // Wachspress (bilinear) interpolation of it.
    for (glm::dvec3 x : {glm::dvec3(0.0), glm::dvec3(0.13, -0.27, 0), glm::dvec3(-0.3, 0.35, 0)}) {
        const ProbeReading r = probe.measure(x, {0, 0, 1}, b);
        for (int band = 0; band < 3; ++band) {
            CHECK(r.interpolatedRadiosity.value()[band] == doctest::Approx(field(x)[band]).epsilon(1e-12).scale(0));
        }
    }
    // Wachspress coordinates: barycentric on a triangle.
    const std::array<glm::dvec3, 3> triangle{{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}};
    const auto w = wachspressCoordinates(triangle, {0, 0, 1}, {0.5, 0.25, 0});
    CHECK(w[0] == doctest::Approx(0.5).scale(0));
    CHECK(w[1] == doctest::Approx(0.25).scale(0));
    CHECK(w[2] == doctest::Approx(0.25).scale(0));
}

TEST_CASE("radiosity does not bleed around a crease of one surface") {
    // One surface folded into an L: a floor square and a wall square sharing an edge. The floor
    // carries B = 1 and the wall B = 5; near the shared edge the floor must still read 1.
    Scene scene;
    scene.name = "fold";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb{}});
    Face floor, wall;
    floor.vertices = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    wall.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    floor.updateGeometry();
    wall.updateGeometry();
    REQUIRE(floor.normal.y == doctest::Approx(1.0).scale(0));
    REQUIRE(wall.normal.z == doctest::Approx(1.0).scale(0));
    scene.surfaces.push_back({"fold", 0, {floor, wall}, "test"});
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.04));
    std::vector<Rgb> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p) b[p] = Rgb(mesh.patches[p].face == 0 ? 1.0 : 5.0);
    const Probe probe(scene, mesh, nullptr);
    const ProbeReading onFloor = probe.measure(glm::dvec3(0.5, 0, 0.01), {0, 1, 0}, b);
    const ProbeReading onWall = probe.measure(glm::dvec3(0.5, 0.01, 0), {0, 0, 1}, b);
    CHECK(onFloor.interpolatedRadiosity.value().x == doctest::Approx(1.0).epsilon(1e-12).scale(0));
    CHECK(onWall.interpolatedRadiosity.value().x == doctest::Approx(5.0).epsilon(1e-12).scale(0));
}

TEST_CASE("a point off every surface or a normal into the surface is refused") {
    const Scene scene = parallelSquares(1.0);
    const PatchMesh mesh = meshScene(scene, probeMeshing(0.05));
    const Probe probe(scene, mesh, nullptr);
    CHECK_THROWS_AS((void)probe.locate({0, 0, 0.3}, {0, 0, 1}), RadiantError);
    CHECK_THROWS_AS((void)probe.locate({0.7, 0, 0}, {0, 0, 1}), RadiantError);
    CHECK_THROWS_AS((void)probe.locate({0, 0, 0}, {0, 0, -1}), RadiantError);
    CHECK_THROWS_AS((void)probe.locate({0, 0, 0}, {0, 0, 0}), RadiantError);
    CHECK(probe.locate({0.1, 0.1, 1.0}, {0, 0, -1}).surface == 1);
}

TEST_CASE("radiant probe on the built-in parallel plates prints the closed forms") {
    // The built-in: emitter [0,1]^2 at y = 0 facing +y (exitance 1, black), receiver at y = 1.
    // At the receiver's centre the emitter is four 0.5 x 0.5 corner rectangles 1 m away; the black
    // emitter's radiosity is exactly its exitance, so E = F x 1 W/m^2.
    const std::string output = "/tmp/radiant-test-probe-" + std::to_string(::getpid()) + ".json";
    const std::string command = std::string(RADIANT_BINARY) +
                                " probe parallel-plates --max-patch-area 0.01 --point 0.5,1,0.5 --normal 0,-1,0 --target emitter --json " +
                                output;
    REQUIRE(std::system(command.c_str()) == 0);
    std::ifstream in(output);
    const nlohmann::json j = nlohmann::json::parse(in);
    std::remove(output.c_str());
    const double F = 4 * pointToCornerRectangle(0.5, 0.5, 1.0);
    const double omega = 4 * cornerRectangleSolidAngle(0.5, 0.5, 1.0);
    CHECK(j["surface"] == "receiver");
    CHECK(j["target"]["name"] == "emitter");
    CHECK(std::abs(j["target"]["form_factor"].get<double>() - F) < 1e-4);
    CHECK(std::abs(j["target"]["projected_solid_angle_sr"].get<double>() - kPi * F) < 1e-4);
    CHECK(std::abs(j["target"]["solid_angle_sr"].get<double>() - omega) < 1e-4);
    for (int band = 0; band < 3; ++band) {
        CHECK(std::abs(j["irradiance_W_m2"][band].get<double>() - F) < 1e-4);
        CHECK(j["radiance_W_m2_sr"][band].get<double>() ==
              doctest::Approx(j["radiosity_W_m2"][band].get<double>() / kPi).epsilon(1e-12).scale(0));
    }
    // A bad vector exits 2 with one line naming the option.
    CHECK(std::system((std::string(RADIANT_BINARY) + " probe parallel-plates --point 0.5,1 --normal 0,-1,0 2>/dev/null")
                          .c_str()) != 0);
}

TEST_CASE("the Probe panel refreshes its readings at most four times a second, and backs off from slow gathers") {
    using app::ProbePanel;
    const auto ms = [](double seconds) {
        return std::chrono::duration<double, std::milli>(ProbePanel::refreshInterval(seconds)).count();
    };
    CHECK(ms(0.0) == doctest::Approx(250));
    CHECK(ms(0.01) == doctest::Approx(250));  // the lab's default mesh: a gather of a few milliseconds
    // A gather of 100 ms (a fine mesh, or two in comparison mode) waits 8 times as long: the
    // readings take at most an eighth of a background core.
    CHECK(ms(0.1) == doctest::Approx(800));
}

} // TEST_SUITE
