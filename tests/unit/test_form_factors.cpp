// ctest-labels: threads
// Form factors against closed forms from Howell's catalog and the lecture (docs/reference.md),
// computed here from the formulas, for several dimensions each.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/formfactor/FormFactor.h"

#include "tests/support/CatalogViewFactors.h"

using namespace radiant;
using radiant::test::parallelRectangles;
using radiant::test::perpendicularRectangles;

namespace {

constexpr double pi = std::numbers::pi;

/// A PatchPolygon built here (independently of the mesher) with its normal turned to `facing`.
PatchPolygon polygonFacing(std::initializer_list<glm::dvec3> corners, const glm::dvec3& facing) {
    PatchPolygon polygon;
    for (const glm::dvec3& c : corners) polygon.vertices[polygon.count++] = c;
    glm::dvec3 doubleArea(0.0);
    for (std::size_t i = 1; i + 1 < polygon.count; ++i)
        doubleArea += glm::cross(polygon.vertices[i] - polygon.vertices[0], polygon.vertices[i + 1] - polygon.vertices[0]);
    if (glm::dot(doubleArea, facing) < 0) {
        std::reverse(polygon.vertices.begin(), polygon.vertices.begin() + polygon.count);
        doubleArea = -doubleArea;
    }
    polygon.area = 0.5 * glm::length(doubleArea);
    polygon.normal = glm::normalize(doubleArea);
    glm::dvec3 weighted(0.0);
    for (std::size_t i = 1; i + 1 < polygon.count; ++i) {
        const double a = 0.5 * glm::length(glm::cross(polygon.vertices[i] - polygon.vertices[0],
                                                      polygon.vertices[i + 1] - polygon.vertices[0]));
        weighted += a * (polygon.vertices[0] + polygon.vertices[i] + polygon.vertices[i + 1]) / 3.0;
    }
    polygon.centroid = weighted / polygon.area;
    return polygon;
}



/// Howell: differential area to a parallel rectangle a x b with a corner on its normal at distance c.
double cornerRectangle(double a, double b, double c) {
    const double A = a / c, B = b / c;
    const double sA = std::sqrt(1 + A * A), sB = std::sqrt(1 + B * B);
    return 1 / (2 * pi) * (A / sA * std::atan(B / sA) + B / sB * std::atan(A / sB));
}

/// Howell: differential area to a rectangle a (along the element's plane) x b (up its normal) in a
/// perpendicular plane at distance c, one edge in the element's plane, one corner opposite x.
double perpendicularRectangleElement(double a, double b, double c) {
    const double s = std::sqrt(b * b + c * c);
    return 1 / (2 * pi) * (std::atan(a / c) - c / s * std::atan(a / s));
}

double diskElement(double r, double h) { return r * r / (h * h + r * r); }

PatchPolygon parallelFrom(double a, double b) {
    return polygonFacing({{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}}, {0, 0, 1});
}
PatchPolygon parallelTo(double a, double b, double c) {
    return polygonFacing({{0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}}, {0, 0, -1});
}

} // namespace

TEST_SUITE("formfactor") {

TEST_CASE("the oracles reproduce the catalog's published values") {
    CHECK(parallelRectangles(1, 1, 1) == doctest::Approx(0.199825).epsilon(1e-5).scale(0));
    CHECK(parallelRectangles(1, 1.5, 0.5) == doctest::Approx(0.4756).epsilon(1e-4).scale(0));
    CHECK(perpendicularRectangles(1, 1, 1) == doctest::Approx(0.200044).epsilon(1e-5).scale(0));
    CHECK(parallelRectangles(1, 1, 1) + 4 * perpendicularRectangles(1, 1, 1) == doctest::Approx(1).epsilon(1e-5).scale(0));
}

TEST_CASE("point to polygon: differential area to the corner of a parallel rectangle, to 1e-6") {
    for (const auto& values : std::array<std::array<double, 3>, 5>{
             {{1, 1, 1}, {2, 0.5, 1}, {0.1, 3, 0.7}, {5, 5, 0.2}, {0.01, 0.02, 1}}}) {
        const double a = values[0], b = values[1], c = values[2];  // not a structured binding: clang 14 cannot CAPTURE those
        const std::array<glm::dvec3, 4> rectangle{{{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}}};  // faces -z
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(c);
        CHECK(std::abs(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rectangle) - cornerRectangle(a, b, c)) < 1e-6);
        // Seen from its back the rectangle contributes nothing.
        const std::array<glm::dvec3, 4> reversed{rectangle[3], rectangle[2], rectangle[1], rectangle[0]};
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, reversed) == 0.0);
    }
}

TEST_CASE("point to polygon: a fine regular polygon approaches the coaxial disk r^2/(h^2+r^2)") {
    for (const auto & values : std::array<std::array<double, 2>, 4>{{{1, 1}, {0.3, 2}, {2, 0.5}, {10, 1}}}) {
        for (const std::size_t sides : {64u, 512u, 4096u}) {
        const double r = values[0], h = values[1];  // not a structured binding: clang 14 cannot CAPTURE those
            std::vector<glm::dvec3> polygon(sides);
            for (std::size_t k = 0; k < sides; ++k) {
                const double angle = -2 * pi * static_cast<double>(k) / static_cast<double>(sides);  // faces -z
                polygon[k] = {r * std::cos(angle), r * std::sin(angle), h};
            }
            const double F = pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, polygon);
            CAPTURE(r);
            CAPTURE(h);
            CAPTURE(sides);
            // The polygon lies between its inscribed and its circumscribed disks.
            CHECK(F > diskElement(r * std::cos(pi / static_cast<double>(sides)), h));
            CHECK(F < diskElement(r, h));
            if (sides == 4096) CHECK(std::abs(F - diskElement(r, h)) < 1e-6);
        }
    }
}

TEST_CASE("point to polygon: the part below the tangent plane is clipped away") {
    // A rectangle in the plane y = c facing x, reaching from depth d below x's tangent plane to
    // height b above it: only the part above counts (Howell's perpendicular-element formula).
    for (const auto & values : std::array<std::array<double, 4>, 4>{
             {{1, 1, 1, 0.5}, {2, 0.3, 0.5, 3}, {0.2, 4, 1.5, 0.01}, {1, 1, 1, 0}}}) {
        const double a = values[0], b = values[1], c = values[2], d = values[3];  // not a structured binding: clang 14 cannot CAPTURE those
        const std::array<glm::dvec3, 4> rectangle{{{0, c, -d}, {a, c, -d}, {a, c, b}, {0, c, b}}};  // faces -y
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(c);
        CAPTURE(d);
        CHECK(std::abs(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rectangle) - perpendicularRectangleElement(a, b, c)) <
              1e-6);
        // Entirely below: nothing.
        const std::array<glm::dvec3, 4> below{{{0, c, -d - 1}, {a, c, -d - 1}, {a, c, -d}, {0, c, -d}}};
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, below) == 0.0);
    }
}

TEST_CASE("point to polygon: a tilted tangent plane through a polygon matches brute-force area integration") {
    // Independent route: F = integral over the polygon of max(0, cos t) cos t' / (pi r^2) dA by the
    // midpoint rule on a fine grid, the clipping done by the max().
    const std::array<glm::dvec3, 3> normals{glm::normalize(glm::dvec3{0.3, -0.4, 1}), glm::normalize(glm::dvec3{-1, 0.2, 0.5}),
                                            glm::normalize(glm::dvec3{0.1, 0.7, 0.2})};
    const std::array<glm::dvec3, 4> square{{{-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}}};  // faces -y
    for (const glm::dvec3& n : normals) {
        constexpr int cells = 1200;
        const double h = 1.0 / cells;
        double expected = 0;
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j) {
                const glm::dvec3 p{-0.5 + (i + 0.5) * h, 1, -0.5 + (j + 0.5) * h};
                const double r2 = glm::dot(p, p);
                const double cosFrom = std::max(0.0, glm::dot(n, p)) / std::sqrt(r2);
                const double cosTo = p.y / std::sqrt(r2);
                expected += cosFrom * cosTo / (pi * r2) * h * h;
            }
        CAPTURE(n.x);
        CHECK(std::abs(pointToPolygonFormFactor({0, 0, 0}, n, square) - expected) < 1e-6);
    }
}

TEST_CASE("patch to patch: parallel directly opposed rectangles within 0.2%") {
    for (const auto & values : std::array<std::array<double, 3>, 6>{
             {{1, 1, 1}, {1, 1.5, 0.5}, {2, 0.5, 0.3}, {0.2, 0.3, 2}, {1, 1, 0.05}, {3, 1, 10}}}) {
        const double a = values[0], b = values[1], c = values[2];  // not a structured binding: clang 14 cannot CAPTURE those
        const double expected = parallelRectangles(a, b, c);
        const double F = formFactor(parallelFrom(a, b), parallelTo(a, b, c), nullptr);
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(c);
        CHECK(F == doctest::Approx(expected).epsilon(2e-3).scale(0));
        // Asked for more, the quadrature delivers more.
        CHECK(unoccludedFormFactor(parallelFrom(a, b), parallelTo(a, b, c), 1e-6) == doctest::Approx(expected).epsilon(1e-5).scale(0));
    }
}

TEST_CASE("patch to patch: perpendicular rectangles sharing an edge within 0.2%") {
    for (const auto & values : std::array<std::array<double, 3>, 6>{
             {{1, 1, 1}, {0.5, 2, 1}, {2, 0.5, 1}, {0.1, 1, 1}, {3, 3, 0.5}, {1, 0.05, 2}}}) {
        const double w = values[0], h = values[1], l = values[2];  // not a structured binding: clang 14 cannot CAPTURE those
        // from: w x l in z = 0 (y in [0, w]); to: h x l in y = 0 (z in [0, h]); shared edge along x.
        const PatchPolygon from = polygonFacing({{0, 0, 0}, {l, 0, 0}, {l, w, 0}, {0, w, 0}}, {0, 0, 1});
        const PatchPolygon to = polygonFacing({{0, 0, 0}, {l, 0, 0}, {l, 0, h}, {0, 0, h}}, {0, 1, 0});
        CAPTURE(w);
        CAPTURE(h);
        CAPTURE(l);
        CHECK(formFactor(from, to, nullptr) == doctest::Approx(perpendicularRectangles(w, h, l)).epsilon(2e-3).scale(0));
        CHECK(formFactor(to, from, nullptr) == doctest::Approx(perpendicularRectangles(h, w, l)).epsilon(2e-3).scale(0));
        CHECK(unoccludedFormFactor(from, to, 1e-5) == doctest::Approx(perpendicularRectangles(w, h, l)).epsilon(1e-4).scale(0));
    }
}

TEST_CASE("patch to patch: reciprocity A_i F_ij = A_j F_ji for random pairs, adjacent ones included") {
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> unit(-1, 1);
    const auto randomDirection = [&] {
        glm::dvec3 d;
        do d = {unit(random), unit(random), unit(random)};
        while (glm::dot(d, d) > 1 || glm::dot(d, d) < 1e-4);
        return glm::normalize(d);
    };
    // A random triangle or convex quad (a parallelogram or a trapezoid-like quad) with a corner at `centre`.
    const auto randomPolygon = [&](const glm::dvec3& centre, const glm::dvec3& normal) {
        const glm::dvec3 t = glm::normalize(glm::cross(normal, randomDirection()));
        const glm::dvec3 s = glm::cross(normal, t);
        const double a = 0.2 + std::abs(unit(random)), b = 0.2 + std::abs(unit(random)), skew = 0.5 * a * unit(random);
        switch (random() % 3) {
        case 0: return polygonFacing({centre, centre + a * t, centre + b * s + skew * t}, normal);
        case 1: return polygonFacing({centre, centre + a * t, centre + a * t + b * s + skew * t, centre + b * s + skew * t}, normal);
        default:
            return polygonFacing({centre, centre + a * t, centre + 1.3 * a * t + b * s, centre + b * s + skew * t}, normal);
        }
    };
    int pairs = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec3 centreA = 2.0 * glm::dvec3{unit(random), unit(random), unit(random)};
        const glm::dvec3 centreB = trial % 4 == 0 ? centreA : 2.0 * glm::dvec3{unit(random), unit(random), unit(random)};
        const PatchPolygon a = randomPolygon(centreA, randomDirection());
        const PatchPolygon b = randomPolygon(centreB, randomDirection());
        const double ab = formFactor(a, b, nullptr);
        const double ba = formFactor(b, a, nullptr);
        if (ab < 1e-4 && ba < 1e-4) continue;
        ++pairs;
        CAPTURE(trial);
        CHECK(a.area * ab == doctest::Approx(b.area * ba).epsilon(1e-3).scale(0));
    }
    CHECK(pairs > 50);
}

TEST_CASE("patch to patch: every row of a unit cube's faces, split n x n, sums to 1") {
    struct CubeFace {
        glm::dvec3 origin, edgeU, edgeV, inward;
    };
    const std::array<CubeFace, 6> faces{{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                         {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}},
                                         {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                         {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
                                         {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
                                         {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}}}};
    for (const int n : {1, 2, 3, 4}) {
        std::vector<PatchPolygon> patches;
        for (const CubeFace& face : faces)
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const glm::dvec3 corner = face.origin + face.edgeU * (double(i) / n) + face.edgeV * (double(j) / n);
                    const glm::dvec3 du = face.edgeU / double(n), dv = face.edgeV / double(n);
                    patches.push_back(polygonFacing({corner, corner + du, corner + du + dv, corner + dv}, face.inward));
                }
        double worst = 0;
        for (const PatchPolygon& from : patches) {
            double row = 0;
            for (const PatchPolygon& to : patches) row += formFactor(from, to, nullptr);
            worst = std::max(worst, std::abs(row - 1));
        }
        CAPTURE(n);
        CHECK(worst < 1e-3);
        if (n == 1) {
            CHECK(formFactor(patches[0], patches[1], nullptr) == doctest::Approx(parallelRectangles(1, 1, 1)).epsilon(1e-3).scale(0));
            CHECK(formFactor(patches[0], patches[2], nullptr) == doctest::Approx(perpendicularRectangles(1, 1, 1)).epsilon(1e-3).scale(0));
        }
    }
}

TEST_CASE("patch to patch: coplanar and back-to-back patches exchange nothing") {
    const PatchPolygon floorA = polygonFacing({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1});
    const PatchPolygon floorB = polygonFacing({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}, {0, 0, 1});
    CHECK(formFactor(floorA, floorB, nullptr) == 0.0);
    const PatchPolygon below = polygonFacing({{0, 0, -1}, {1, 0, -1}, {1, 1, -1}, {0, 1, -1}}, {0, 0, -1});
    CHECK(formFactor(floorA, below, nullptr) == 0.0);
    const PatchPolygon above = parallelTo(1, 1, 1);
    const PatchPolygon aboveBackwards = polygonFacing({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {0, 0, 1});
    CHECK(formFactor(floorA, above, nullptr) > 0.19);
    CHECK(formFactor(floorA, aboveBackwards, nullptr) == 0.0);
}

} // TEST_SUITE
