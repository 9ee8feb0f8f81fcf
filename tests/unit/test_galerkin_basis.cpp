// The Galerkin basis (radiometry/galerkin/Basis.h, Quadrature.h) against closed forms: monomial
// integrals for the rules, orthonormality in the area measure by a fine rule with the Jacobian taken
// by differences here, and the mean of a linear function over a polygon (its value at the centroid).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "radiometry/galerkin/Basis.h"
#include "radiometry/galerkin/Quadrature.h"

#include "tests/support/GalerkinElements.h"
#include "tests/support/Relative.h"

// A namespace of its own: unity builds put test files together, and no using-directive leaks out.
namespace radiant::galerkin::basis_tests {

using radiant::test::relativeTo;

namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

double integrate(const QuadratureRule& rule, int a, int b) {
    double sum = 0;
    for (const QuadratureNode& node : rule) sum += node.weight * std::pow(node.at.u, a) * std::pow(node.at.v, b);
    return sum;
}

/// Mean of u^a v^b over the unit square and (normalised) over the unit triangle.
double squareMonomialMean(int a, int b) { return 1.0 / ((a + 1) * (b + 1)); }
double triangleMonomialMean(int a, int b) { return 2 * factorial(a) * factorial(b) / factorial(a + b + 2); }

} // namespace

TEST_CASE("galerkin: quadrature rules integrate monomials exactly to their degree") {
    for (std::size_t n : {1, 2, 3, 5, 16}) {
        const QuadratureRule square = tensorGaussSquareRule(n);
        const int degree = static_cast<int>(2 * n - 1);
        for (int a = 0; a <= degree; ++a)
            for (int b = 0; b <= degree; ++b) {
                INFO("n = " << n << ", u^" << a << " v^" << b);
                CHECK(integrate(square, a, b) == relativeTo(squareMonomialMean(a, b), 1e-13));
            }
    }
    const auto checkTriangle = [](const QuadratureRule& rule, int degree, const char* name) {
        for (int a = 0; a <= degree; ++a)
            for (int b = 0; a + b <= degree; ++b) {
                INFO(name << ": u^" << a << " v^" << b);
                CHECK(integrate(rule, a, b) == relativeTo(triangleMonomialMean(a, b), 1e-13));
            }
    };
    checkTriangle(triangleRule3(), 2, "3-point");
    checkTriangle(triangleRule7(), 5, "Radon's 7");
    checkTriangle(collapsedGaussTriangleRule(8), 14, "collapsed 8 x 8");
    // One degree past exactness the 3- and 7-point rules are wrong: they are the rules they claim to be.
    CHECK(std::abs(integrate(triangleRule3(), 3, 0) - triangleMonomialMean(3, 0)) > 1e-3);
    CHECK(std::abs(integrate(triangleRule7(), 6, 0) - triangleMonomialMean(6, 0)) > 1e-5);
}

TEST_CASE("galerkin: the basis is orthonormal in the normalised area measure on parallelograms and triangles") {
    for (const PatchPolygon& element : {test::tiltedSquare(), test::tiltedParallelogram(), test::tiltedTriangle()}) {
        const ElementShape shape = shapeOf(element);
        const QuadratureRule fine = shape == ElementShape::Quad ? tensorGaussSquareRule(16) : collapsedGaussTriangleRule(16);
        double area = 0;
        std::array<BasisCoefficients, kMaxBasisSize> gram{};
        for (const QuadratureNode& node : fine) {
            const double dA = node.weight * test::jacobianByDifferences(element, node.at.u, node.at.v);
            area += dA;
            const BasisCoefficients phi = basisValues(shape, node.at);
            for (std::size_t i = 0; i < basisSize(shape); ++i)
                for (std::size_t j = 0; j < basisSize(shape); ++j) gram[i][j] += dA * phi[i] * phi[j];
        }
        for (std::size_t i = 0; i < basisSize(shape); ++i)
            for (std::size_t j = 0; j < basisSize(shape); ++j) {
                INFO("corners " << int(element.count) << ", <phi_" << i << ", phi_" << j << "> = " << gram[i][j] / area);
                CHECK(std::abs(gram[i][j] / area - (i == j ? 1.0 : 0.0)) < 1e-9);
            }
    }
}

TEST_CASE("galerkin: a trapezoid's basis is orthonormal in its parameters and its area density is J / A") {
    const PatchPolygon trapezoid = test::tiltedTrapezoid();
    const QuadratureRule fine = tensorGaussSquareRule(16);
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 4; ++j) {
            double inner = 0;
            for (const QuadratureNode& node : fine)
                inner += node.weight * basisValues(ElementShape::Quad, node.at)[i] * basisValues(ElementShape::Quad, node.at)[j];
            CHECK(std::abs(inner - (i == j ? 1.0 : 0.0)) < 1e-12);
        }
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.6, 1.0}) {
            INFO("u = " << u << ", v = " << v);
            CHECK(areaDensity(trapezoid, {u, v}) == relativeTo(test::jacobianByDifferences(trapezoid, u, v) / trapezoid.area, 1e-8));
        }
    // It is a real trapezoid: the density varies by 5.6% between opposite corners (10x the Cornell floor's).
    CHECK(std::abs(areaDensity(trapezoid, {1, 1}) - areaDensity(trapezoid, {0, 0})) > 0.05);
}

TEST_CASE("galerkin: a linear function is represented exactly and its mean is its value at the centroid") {
    // f(x) = 2 + g . (x - o): linear in space, so bilinear in a quad's parameters and linear in a
    // triangle's, inside the basis's span; the mean of a linear function over a polygon is its value
    // at the area centroid (closed form, for any polygon).
    const glm::dvec3 g(0.7, -1.3, 0.4), o(0.1, 0.2, 0.3);
    const auto f = [&](const glm::dvec3& x) { return 2 + glm::dot(g, x - o); };
    for (const PatchPolygon& element :
         {test::tiltedSquare(), test::tiltedParallelogram(), test::tiltedTrapezoid(), test::tiltedTriangle()}) {
        const ElementShape shape = shapeOf(element);
        const BasisCoefficients c = projectOntoBasis(shape, elementRule(shape, 3), [&](ElementParameter at) {
            return f(test::mapOfCorners(element, at.u, at.v));
        });
        INFO("corners " << int(element.count) << ", area " << element.area);
        CHECK(elementMean(element, c) == relativeTo(f(element.centroid), 1e-12));
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(0, 1);
        for (int sample = 0; sample < 20; ++sample) {
            double u = unit(random), v = unit(random);
            if (shape == ElementShape::Triangle && u + v > 1) u = 1 - u, v = 1 - v;
            CHECK(valueAt(shape, c, {u, v}) == relativeTo(f(test::mapOfCorners(element, u, v)), 1e-12));
            CHECK(glm::length(pointAt(element, {u, v}) - test::mapOfCorners(element, u, v)) < 1e-14);
        }
    }
}

TEST_CASE("galerkin: the mean of any basis function on a trapezoid is its area-weighted integral") {
    // The part of elementMean that the centroid test leaves out: the bilinear term, and functions
    // that are not linear in space. Against a 16 x 16 rule weighted by the Jacobian taken by differences.
    const PatchPolygon trapezoid = test::tiltedTrapezoid();
    const QuadratureRule fine = tensorGaussSquareRule(16);
    const BasisCoefficients c{0.9, -0.35, 0.6, 0.45};
    double weighted = 0, area = 0;
    for (const QuadratureNode& node : fine) {
        const double dA = node.weight * test::jacobianByDifferences(trapezoid, node.at.u, node.at.v);
        weighted += dA * valueAt(ElementShape::Quad, c, node.at);
        area += dA;
    }
    CHECK(area == relativeTo(trapezoid.area, 1e-9));
    CHECK(elementMean(trapezoid, c) == relativeTo(weighted / area, 1e-9));
    // And differs from c_0 there by the density's correlation with the linear terms.
    CHECK(std::abs(elementMean(trapezoid, c) - c[0]) > 1e-3);
}

} // namespace radiant::galerkin::basis_tests
