// ctest-labels: threads
// Ray casting and visibility: picks return the right surface, face, point and normal; rays never
// report the surface they start on; a blocker hides the fraction of segments geometry predicts.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/BuiltinScenes.h"

using namespace radiant;

namespace {

/// A face from corners given counter-clockwise seen from its front.
Face faceOf(std::initializer_list<glm::dvec3> corners) {
    Face face;
    face.vertices = corners;
    face.updateGeometry();
    return face;
}

Scene namedSurfacesScene(std::vector<std::pair<std::string, std::vector<Face>>> surfaces) {
    Scene scene;
    scene.name = "test scene";
    scene.materials.push_back({"grey", Rgb{0.5}, ExitanceRgb{}});
    for (auto& [name, faces] : surfaces) scene.surfaces.push_back({name, 0, std::move(faces), "test"});
    return scene;
}

PatchPolygon polygonOf(const Face& face) {
    PatchPolygon polygon;
    for (const glm::dvec3& v : face.vertices) polygon.vertices[polygon.count++] = v;
    polygon.normal = face.normal;
    polygon.area = face.area;
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& v : face.vertices) sum += v;
    polygon.centroid = sum / static_cast<double>(face.vertices.size());  // exact for the parallelograms used here
    return polygon;
}

/// The inside of the unit cube, each face split into n x n square faces facing inwards.
Scene cubeInterior(int n) {
    struct Side {
        glm::dvec3 origin, edgeU, edgeV;
    };
    // edgeU x edgeV points into the cube.
    const std::array<Side, 6> sides{{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                     {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}},
                                     {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}},
                                     {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
                                     {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                     {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}}}};
    std::vector<std::pair<std::string, std::vector<Face>>> surfaces;
    for (std::size_t s = 0; s < sides.size(); ++s) {
        std::vector<Face> faces;
        const Side& side = sides[s];
        const glm::dvec3 du = side.edgeU / double(n), dv = side.edgeV / double(n);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const glm::dvec3 corner = side.origin + du * double(i) + dv * double(j);
                faces.push_back(faceOf({corner, corner + du, corner + du + dv, corner + dv}));
            }
        surfaces.emplace_back("side " + std::to_string(s), std::move(faces));
    }
    return namedSurfacesScene(std::move(surfaces));
}

} // namespace

TEST_SUITE("formfactor") {

TEST_CASE("ray caster: picks return the surface, face, point, normal and distance") {
    const Scene scene = namedSurfacesScene({
        {"floor", {faceOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), faceOf({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}})}},
        {"wall", {faceOf({{3, 0, 0}, {3, 0, 1}, {3, 1, 1}, {3, 1, 0}})}},  // faces -x
        // A pentagon, so that some hits land in its second or third fan triangle.
        {"pentagon", {faceOf({{0, 0, 2}, {1, 0, 2}, {1.3, 0.6, 2}, {0.5, 1, 2}, {-0.3, 0.6, 2}})}},
    });
    CHECK(scene.surfaces[1].faces[0].normal.x == doctest::Approx(-1).scale(0));
    const RayCaster rays(scene);

    auto hit = rays.intersect({0.5, 0.25, 1}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->surface == 0);
    CHECK(hit->face == 0);
    CHECK(hit->distance == doctest::Approx(1).scale(0));
    CHECK(glm::length(hit->point - glm::dvec3{0.5, 0.25, 0}) < 1e-7);
    CHECK(glm::length(hit->normal - glm::dvec3{0, 0, 1}) < 1e-12);

    hit = rays.intersect({1.7, 0.9, 1.5}, {0, 0, -3});  // a direction that is not unit
    REQUIRE(hit);
    CHECK(hit->surface == 0);
    CHECK(hit->face == 1);
    CHECK(hit->distance == doctest::Approx(1.5).scale(0));
    CHECK(glm::length(hit->point - glm::dvec3{1.7, 0.9, 0}) < 1e-7);

    hit = rays.intersect({1, 0.5, 0.5}, glm::dvec3{2, 0, 0.2});
    REQUIRE(hit);
    CHECK(hit->surface == 1);
    CHECK(hit->face == 0);
    CHECK(hit->distance == doctest::Approx(std::sqrt(4 + 0.04)).scale(0));
    CHECK(glm::length(hit->point - glm::dvec3{3, 0.5, 0.7}) < 1e-7);
    CHECK(glm::length(hit->normal - glm::dvec3{-1, 0, 0}) < 1e-12);

    // The back of the floor is hit too (the normal still names the front).
    hit = rays.intersect({0.5, 0.5, 1.5}, {0, 0, 1});
    REQUIRE(hit);
    CHECK(hit->surface == 2);
    CHECK(hit->distance == doctest::Approx(0.5).scale(0));
    for (const glm::dvec3& target : {glm::dvec3{1.1, 0.6, 2}, glm::dvec3{0.5, 0.9, 2}, glm::dvec3{-0.2, 0.6, 2}}) {
        hit = rays.intersect({0.5, 0.5, 3}, target - glm::dvec3{0.5, 0.5, 3});
        REQUIRE(hit);
        CHECK(hit->surface == 2);
        CHECK(hit->face == 0);
        CHECK(glm::length(hit->point - target) < 1e-7);
    }

    CHECK_FALSE(rays.intersect({0.5, 0.5, 1}, {0, 0, -1}, 0.9));  // beyond maxDistance
    CHECK_FALSE(rays.intersect({5, 5, 5}, {1, 0, 0}));             // nothing there
    CHECK_FALSE(rays.intersect({0.5, 0.5, 1}, {0, 0, 0}));         // no direction
}

TEST_CASE("ray caster: picks in the Cornell box") {
    const Scene box = makeCornellBox();
    const RayCaster rays(box);
    // From in front of the box straight ahead, above the tall block: the back wall.
    auto hit = rays.intersect({0.278, 0.45, -0.8}, {0, 0, 1});
    REQUIRE(hit);
    CHECK(box.surfaces[hit->surface].name == "back wall");
    CHECK(hit->distance == doctest::Approx(0.8 + 0.5592).scale(0));
    CHECK(hit->normal.z == doctest::Approx(-1).scale(0));
    // Straight down onto the tall block's top at y = 0.33, and up into the light.
    hit = rays.intersect({0.37, 0.5, 0.35}, {0, -1, 0});
    REQUIRE(hit);
    CHECK(box.surfaces[hit->surface].name == "tall block");
    CHECK(hit->point.y == doctest::Approx(0.33).scale(0));
    CHECK(hit->normal.y == doctest::Approx(1).scale(0));
    hit = rays.intersect({0.278, 0.1, 0.28}, {0, 1, 0});
    REQUIRE(hit);
    CHECK(box.surfaces[hit->surface].name == "light");
    CHECK(hit->normal.y == doctest::Approx(-1).scale(0));
}

TEST_CASE("ray caster: rays never report the surface they start on") {
    const Scene cube = cubeInterior(3);
    const RayCaster rays(cube);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    int failures = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const std::size_t s = random() % cube.surfaces.size();
        const Face& face = cube.surfaces[s].faces[random() % cube.surfaces[s].faces.size()];
        const glm::dvec3 p = face.vertices[0] + (face.vertices[1] - face.vertices[0]) * uniform(random) +
                             (face.vertices[3] - face.vertices[0]) * uniform(random);
        // Directions down to nearly grazing (cos = 1e-5 from the surface).
        const double cosTheta = std::max(1e-5, uniform(random));
        const double phi = 2 * std::numbers::pi * uniform(random);
        const glm::dvec3 t = glm::normalize(face.vertices[1] - face.vertices[0]);
        const glm::dvec3 b = glm::cross(face.normal, t);
        const double sinTheta = std::sqrt(1 - cosTheta * cosTheta);
        const glm::dvec3 direction = face.normal * cosTheta + (t * std::cos(phi) + b * std::sin(phi)) * sinTheta;
        const auto hit = rays.intersect(p, direction);
        if (!hit || hit->surface == s || !(hit->distance > 0)) ++failures;
    }
    CHECK(failures == 0);
}

TEST_CASE("visibility: nothing blocks the inside of a convex room, even between neighbours and along a wall") {
    const int n = 3;
    const Scene cube = cubeInterior(n);
    const RayCaster rays(cube);
    std::vector<PatchPolygon> patches;
    for (const Surface& surface : cube.surfaces)
        for (const Face& face : surface.faces) patches.push_back(polygonOf(face));
    FormFactorOptions options;
    options.visibilityRays = 64;
    int blockedPairs = 0;
    for (const PatchPolygon& a : patches)
        for (const PatchPolygon& b : patches)
            if (&a != &b && visibilityFraction(a, b, &rays, options) != 1.0) ++blockedPairs;
    CHECK(blockedPairs == 0);
}

TEST_CASE("visibility: a square blocker halfway between parallel plates hides the predicted fraction") {
    // Segments between uniform points on two unit plates cross the mid-plane at their midpoint,
    // whose coordinates each have the triangular density of a mean of two uniforms: the blocked
    // fraction for a centred s x s blocker is (1 - (1 - s)^2)^2.
    for (const double s : {0.2, 0.5, 0.8}) {
        const double lo = 0.5 - s / 2, hi = 0.5 + s / 2;
        const Scene scene = namedSurfacesScene({
            {"bottom", {faceOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})}},
            {"top", {faceOf({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}})}},
            {"blocker", {faceOf({{lo, lo, 0.5}, {hi, lo, 0.5}, {hi, hi, 0.5}, {lo, hi, 0.5}})}},
        });
        const RayCaster rays(scene);
        const PatchPolygon bottom = polygonOf(scene.surfaces[0].faces[0]);
        const PatchPolygon top = polygonOf(scene.surfaces[1].faces[0]);
        const double blocked = std::pow(1 - (1 - s) * (1 - s), 2);
        FormFactorOptions options;
        options.visibilityRays = 4096;
        const double visible = visibilityFraction(bottom, top, &rays, options);
        // Three binomial standard deviations: stratification only lowers the noise.
        const double noise = 3 * std::sqrt(blocked * (1 - blocked) / options.visibilityRays);
        CAPTURE(s);
        CHECK(std::abs(visible - (1 - blocked)) < noise);
        // Symmetric and deterministic, so reciprocity survives visibility.
        CHECK(visibilityFraction(top, bottom, &rays, options) == visible);
        CHECK(visibilityFraction(bottom, top, &rays, options) == visible);

        options.visibilityRays = 1024;
        const double unoccluded = formFactor(bottom, top, nullptr, options);
        const double occluded = formFactor(bottom, top, &rays, options);
        CHECK(std::abs(occluded / unoccluded - (1 - blocked)) < 3 * std::sqrt(blocked * (1 - blocked) / 1024));
        CHECK(bottom.area * occluded == doctest::Approx(top.area * formFactor(top, bottom, &rays, options)).epsilon(1e-3).scale(0));
    }
}

TEST_CASE("ray caster: occlusion in the Cornell box agrees with clipping segments against the blocks") {
    // Independent route: each block is a convex prism (its faces' planes and the floor); a segment is
    // blocked when Cyrus-Beck clipping against those planes leaves a piece of it.
    const Scene box = makeCornellBox();
    const RayCaster rays(box);
    const auto crossesBlock = [](const Surface& block, const glm::dvec3& p, const glm::dvec3& q) {
        double enter = 0, leave = 1;
        const auto clip = [&](const glm::dvec3& outward, double offset) {
            const double a = glm::dot(outward, p) - offset, b = glm::dot(outward, q) - offset;
            if (a >= 0 && b >= 0) return false;
            if (a < 0 && b < 0) return true;
            const double t = a / (a - b);
            if (a >= 0) enter = std::max(enter, t);
            else leave = std::min(leave, t);
            return true;
        };
        for (const Face& face : block.faces)
            if (!clip(face.normal, glm::dot(face.normal, face.vertices[0]))) return false;
        return clip({0, -1, 0}, 0) && leave - enter > 1e-9;
    };
    const Surface& shortBlock = box.surfaces[box.findSurface("short block")];
    const Surface& tallBlock = box.surfaces[box.findSurface("tall block")];
    const Face& floor = box.surfaces[box.findSurface("floor")].faces[0];
    const Face& ceiling = box.surfaces[box.findSurface("ceiling")].faces[0];
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> uniform(0, 1);
    const auto pointOn = [&](const Face& face) {
        const double u = uniform(random), v = uniform(random);
        return (1 - u) * (1 - v) * face.vertices[0] + u * (1 - v) * face.vertices[1] + u * v * face.vertices[2] +
               (1 - u) * v * face.vertices[3];
    };
    const int segments = 20000;
    int disagreements = 0, blocked = 0;
    std::vector<glm::dvec3> from, to;
    std::vector<char> expectedAll;
    for (int i = 0; i < segments; ++i) {
        const glm::dvec3 p = pointOn(floor), q = pointOn(ceiling);
        const bool expected = crossesBlock(shortBlock, p, q) || crossesBlock(tallBlock, p, q);
        blocked += expected ? 1 : 0;
        disagreements += rays.occluded(p, q) != expected ? 1 : 0;
        from.push_back(p);
        to.push_back(q);
        expectedAll.push_back(expected ? 1 : 0);
    }
    CHECK(blocked > segments / 10);     // the test exercises both outcomes
    CHECK(disagreements <= 2);          // float BVH against double planes: grazing hits may differ

    // The same segments as packets (the span overload), in batches of 1 to 19 so that partly filled
    // packets and several packets per call both occur; an empty segment is never blocked.
    int packetDisagreements = 0;
    std::size_t next = 0;
    for (std::size_t batch = 1; next < from.size(); batch = batch % 19 + 1) {
        const std::size_t count = std::min(batch, from.size() - next);
        std::array<bool, 19> answers{};
        rays.occluded(std::span<const glm::dvec3>(from.data() + next, count), std::span<const glm::dvec3>(to.data() + next, count),
                      std::span<bool>(answers.data(), count));
        for (std::size_t i = 0; i < count; ++i) packetDisagreements += answers[i] != (expectedAll[next + i] != 0) ? 1 : 0;
        next += count;
    }
    CHECK(packetDisagreements <= 2);
    const std::array<glm::dvec3, 2> same{floor.vertices[0] + glm::dvec3(0.1, 0, 0.1), floor.vertices[0] + glm::dvec3(0.1, 0, 0.1)};
    std::array<bool, 1> empty{true};
    rays.occluded(std::span<const glm::dvec3>(same.data(), 1), std::span<const glm::dvec3>(same.data() + 1, 1), std::span<bool>(empty));
    CHECK_FALSE(empty[0]);
}

TEST_CASE("ray caster: packets leave out only the faces bounding the scene") {
    // A floor (it bounds the scene: everything is above it) with a wall standing across its middle
    // (floor corners on both sides of its plane: it can block). Segments from the floor on one side
    // to the floor on the other pass over the wall's top edge or through the wall; a plane test on
    // the wall's rectangle says which. Segments on one side are never blocked.
    const Scene scene = namedSurfacesScene({
        {"floor", {faceOf({{0, 0, 0}, {0, 0, 1}, {2, 0, 1}, {2, 0, 0}})}},
        {"wall", {faceOf({{1, 0, 0}, {1, 0.3, 0}, {1, 0.3, 1}, {1, 0, 1}})}},
    });
    const RayCaster rays(scene);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::vector<glm::dvec3> from, to;
    std::vector<char> expected;
    for (int i = 0; i < 4000; ++i) {
        const bool across = i % 2 == 0;
        const glm::dvec3 p{0.9 * uniform(random), 0.5 * uniform(random) * (i % 3 == 0 ? 1 : 0), uniform(random)};
        const glm::dvec3 q{across ? 1.1 + 0.9 * uniform(random) : 0.9 * uniform(random), 0.5 * uniform(random), uniform(random)};
        const double t = across ? (1 - p.x) / (q.x - p.x) : -1;
        const glm::dvec3 atWall = p + t * (q - p);
        from.push_back(p);
        to.push_back(q);
        expected.push_back(across && atWall.y < 0.3 && atWall.z > 0 && atWall.z < 1 ? 1 : 0);
    }
    int disagreements = 0, blocked = 0;
    for (std::size_t first = 0; first < from.size(); first += 8) {
        std::array<bool, 8> answers{};
        rays.occluded(std::span<const glm::dvec3>(from.data() + first, 8), std::span<const glm::dvec3>(to.data() + first, 8),
                      std::span<bool>(answers));
        for (std::size_t i = 0; i < 8; ++i) {
            disagreements += answers[i] != (expected[first + i] != 0) ? 1 : 0;
            blocked += expected[first + i];
        }
    }
    CHECK(blocked > 400);
    CHECK(disagreements <= 2);
    // The faces it leaves out, as mayBlock reports them (the hierarchical solver's shafts skip them).
    CHECK_FALSE(rays.mayBlock(0));
    CHECK(rays.mayBlock(1));
    const Scene box = makeCornellBox();
    const RayCaster boxRays(box);
    std::size_t face = 0;
    for (const Surface& surface : box.surfaces)
        for (std::size_t f = 0; f < surface.faces.size(); ++f) {
            CAPTURE(surface.name);
            CHECK(boxRays.mayBlock(face++) == (surface.name.find("block") != std::string::npos));
        }
    CHECK(boxRays.mayBlock(face));  // past the last face: nothing known, so it may
}

TEST_CASE("visibility: concurrent queries on one ray caster agree with sequential ones") {
    // The Cornell box's blocks hide part of the floor from the ceiling: fractions strictly between
    // 0 and 1, computed for the same pairs on two threads at once and then on one.
    const Scene box = makeCornellBox();
    const RayCaster rays(box);
    std::vector<PatchPolygon> floorAndCeiling;
    for (const char* name : {"floor", "ceiling"})
        for (const Face& face : box.surfaces[box.findSurface(name)].faces) floorAndCeiling.push_back(polygonOf(face));
    FormFactorOptions options;
    options.visibilityRays = 256;
    const std::size_t pairs = floorAndCeiling.size() - 1;
    std::vector<double> concurrent(2 * pairs);
    {
        std::vector<std::jthread> threads;
        for (std::size_t t = 0; t < 2; ++t)
            threads.emplace_back([&, t] {
                for (std::size_t k = 0; k < pairs; ++k)
                    concurrent[t * pairs + k] = visibilityFraction(floorAndCeiling[0], floorAndCeiling[k + 1], &rays, options);
            });
    }
    for (std::size_t k = 0; k < pairs; ++k) {
        const double sequential = visibilityFraction(floorAndCeiling[0], floorAndCeiling[k + 1], &rays, options);
        CHECK(concurrent[k] == sequential);
        CHECK(concurrent[pairs + k] == sequential);
    }
    const double floorToCeiling = visibilityFraction(floorAndCeiling[0], floorAndCeiling[1], &rays, options);
    CHECK(floorToCeiling > 0.2);
    CHECK(floorToCeiling < 1.0);
}

TEST_CASE("visibility: without a ray caster or rays, everything is visible") {
    const PatchPolygon a = polygonOf(faceOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    const PatchPolygon b = polygonOf(faceOf({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}));
    CHECK(visibilityFraction(a, b, nullptr) == 1.0);
    const Scene empty = namedSurfacesScene({});
    const RayCaster rays(empty);
    FormFactorOptions none;
    none.visibilityRays = 0;
    CHECK(visibilityFraction(a, b, &rays, none) == 1.0);
    CHECK(visibilityFraction(a, b, &rays) == 1.0);
}

} // TEST_SUITE
