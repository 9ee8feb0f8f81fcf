// The exact polygon solid angle (Van Oosterom & Strackee) against the closed forms of docs/reference.md:
// the corner rectangle atan(ab / (h sqrt(a^2 + b^2 + h^2))), the cap 2 pi (1 - cos alpha), and the
// faces of a regular dodecahedron (4 pi / 12 each).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"
#include "radiometry/solidangle/PolygonSolidAngle.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {
using radiant::test::kPi;

double cornerRectangleOracle(double a, double b, double h) {  // the oracle, written out in the test
    return std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h)));
}

/// Axis-aligned rectangle [x0, x1] x [y0, y1] in the plane z = 0, counter-clockwise seen from +z.
std::vector<glm::dvec3> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
}
} // namespace

TEST_SUITE("core") {

TEST_CASE("a rectangle seen from above its corner matches the closed form to 1e-9") {
    for (double a : {0.1, 1.0, 2.5})
        for (double b : {0.3, 1.0, 7.0})
            for (double h : {0.05, 1.0, 4.0}) {
                CAPTURE(a);
                CAPTURE(b);
                CAPTURE(h);
                const double expected = cornerRectangleOracle(a, b, h);
                const auto polygon = rectangle(0, 0, a, b);
                CHECK(signedPolygonSolidAngle({0, 0, h}, polygon).value() ==
                      doctest::Approx(expected).epsilon(1e-9).scale(0));
                CHECK(cornerRectangleSolidAngle(Length(a), Length(b), Length(h)).value() ==
                      doctest::Approx(expected).epsilon(1e-12).scale(0));
            }
    CHECK(cornerRectangleOracle(1, 1, 1) == doctest::Approx(kPi / 6).epsilon(1e-14).scale(0));
}

TEST_CASE("a point above the inside, outside, or behind a rectangle: sums and differences of corners") {
    const auto polygon = rectangle(-1.0, -0.5, 2.0, 1.5);
    for (double h : {0.2, 1.0, 3.0}) {
        CAPTURE(h);
        // Above an interior point: four corner rectangles around the foot of the perpendicular.
        const double inside = cornerRectangleOracle(1.0, 0.5, h) + cornerRectangleOracle(2.0, 0.5, h) +
                              cornerRectangleOracle(1.0, 1.5, h) + cornerRectangleOracle(2.0, 1.5, h);
        CHECK(signedPolygonSolidAngle({0, 0, h}, polygon).value() == doctest::Approx(inside).epsilon(1e-9).scale(0));
        // From behind: the same magnitude, negative sign.
        CHECK(signedPolygonSolidAngle({0, 0, -h}, polygon).value() == doctest::Approx(-inside).epsilon(1e-9).scale(0));
        CHECK(polygonSolidAngle({0, 0, -h}, polygon).value() == doctest::Approx(inside).epsilon(1e-9).scale(0));
        // Above a point outside the rectangle (x = 3): the difference of two corner rectangles per side.
        const double outside = cornerRectangleOracle(4.0, 0.5, h) - cornerRectangleOracle(1.0, 0.5, h) +
                               cornerRectangleOracle(4.0, 1.5, h) - cornerRectangleOracle(1.0, 1.5, h);
        CHECK(signedPolygonSolidAngle({3, 0, h}, polygon).value() == doctest::Approx(outside).epsilon(1e-9).scale(0));
    }
    // Very close above the inside, a large polygon fills nearly the whole hemisphere.
    CHECK(polygonSolidAngle({0, 0, 1e-6}, rectangle(-1e3, -1e3, 1e3, 1e3)).value() ==
          doctest::Approx(2 * kPi).epsilon(1e-6).scale(0));
    CHECK(polygonSolidAngle({0.3, 0.2, 0}, polygon).value() == 0.0);  // in its plane: seen edge-on
    CHECK_THROWS_AS(polygonSolidAngle({0, 0, 1}, std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}}), RadiantError);
}

TEST_CASE("a fine regular polygon approaches the cap 2 pi (1 - cos alpha)") {
    for (double h : {0.5, 1.0, 3.0}) {
        const double radius = 1.0;
        const double alpha = std::atan(radius / h);
        const double cap = 2 * kPi * (1 - std::cos(alpha));
        CHECK(coneSolidAngle(Radians(alpha)).value() == doctest::Approx(cap).epsilon(1e-12).scale(0));
        double previousError = 1e9;
        for (int sides : {16, 64, 256, 1024, 4096}) {
            std::vector<glm::dvec3> polygon;
            for (int k = 0; k < sides; ++k) {
                const double angle = 2 * kPi * k / sides;
                polygon.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
            }
            const double error = std::abs(polygonSolidAngle({0, 0, h}, polygon).value() - cap);
            CAPTURE(h);
            CAPTURE(sides);
            CHECK(error < previousError / 10);  // the inscribed polygon's deficit falls like 1/sides^2
            previousError = error;
        }
        CHECK(previousError / cap < 1e-6);
    }
    CHECK(coneSolidAngle(Radians(kPi / 2)).value() == doctest::Approx(2 * kPi).epsilon(1e-14).scale(0));
    CHECK(coneSolidAngle(Radians(kPi)).value() == doctest::Approx(4 * kPi).epsilon(1e-14).scale(0));
}

TEST_CASE("each face of a regular dodecahedron subtends 4 pi / 12 at its centre, and the 12 sum to 4 pi") {
    const double phi = (1 + std::sqrt(5.0)) / 2;
    std::vector<glm::dvec3> vertices;
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) vertices.push_back({x, y, z});
    for (double s : {-1.0, 1.0})
        for (double t : {-1.0, 1.0}) {
            vertices.push_back({0, s / phi, t * phi});
            vertices.push_back({s / phi, t * phi, 0});
            vertices.push_back({s * phi, 0, t / phi});
        }
    REQUIRE(vertices.size() == 20);
    // The face normals point at the vertices of the dual icosahedron.
    std::vector<glm::dvec3> normals;
    for (double s : {-1.0, 1.0})
        for (double t : {-1.0, 1.0}) {
            normals.push_back(glm::normalize(glm::dvec3(0, s * phi, t)));
            normals.push_back(glm::normalize(glm::dvec3(s * phi, t, 0)));
            normals.push_back(glm::normalize(glm::dvec3(t, 0, s * phi)));
        }
    REQUIRE(normals.size() == 12);
    double total = 0;
    for (const glm::dvec3& n : normals) {
        // The face: the five vertices farthest along n, ordered counter-clockwise about n.
        std::vector<glm::dvec3> face = vertices;
        std::sort(face.begin(), face.end(),
                  [&](const glm::dvec3& p, const glm::dvec3& q) { return glm::dot(p, n) > glm::dot(q, n); });
        face.resize(5);
        REQUIRE(glm::dot(face[4], n) == doctest::Approx(glm::dot(face[0], n)).scale(0));
        const glm::dvec3 centre = (face[0] + face[1] + face[2] + face[3] + face[4]) / 5.0;
        const glm::dvec3 u = glm::normalize(face[0] - centre);
        const glm::dvec3 v = glm::cross(n, u);
        std::sort(face.begin(), face.end(), [&](const glm::dvec3& p, const glm::dvec3& q) {
            return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
                   std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
        });
        const double signedOmega = signedPolygonSolidAngle({0, 0, 0}, face).value();
        CHECK(signedOmega < 0);  // the centre lies behind every outward-facing face
        CHECK(-signedOmega == doctest::Approx(4 * kPi / 12).epsilon(1e-12).scale(0));
        total += -signedOmega;
    }
    CHECK(total == doctest::Approx(4 * kPi).epsilon(1e-12).scale(0));
    CHECK(regularSolidFaceSolidAngle(12).value() == doctest::Approx(1.0472).epsilon(1e-4).scale(0));
    CHECK_THROWS_AS(regularSolidFaceSolidAngle(7), RadiantError);
}

TEST_CASE("A/R^2 holds for a small far square and fails close up") {
    const double side = 1.0;
    double previousError = 1e9;
    for (double distance : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 64.0}) {
        const double exact = 4 * cornerRectangleOracle(side / 2, side / 2, distance);
        const double approximate = smallAreaSolidAngle(Area(side * side), Length(distance)).value();
        const double relativeError = std::abs(approximate - exact) / exact;
        CAPTURE(distance);
        CHECK(relativeError < previousError);
        if (distance == 0.5) CHECK(relativeError > 0.5);
        previousError = relativeError;
        // and the exact polygon route agrees with the closed form at every distance
        CHECK(polygonSolidAngle({0, 0, distance}, rectangle(-0.5, -0.5, 0.5, 0.5)).value() ==
              doctest::Approx(exact).epsilon(1e-9).scale(0));
    }
    CHECK(previousError < 1e-3);
    CHECK_THROWS_AS(smallAreaSolidAngle(Area(1.0), Length(0.0)), RadiantError);
}

} // TEST_SUITE
