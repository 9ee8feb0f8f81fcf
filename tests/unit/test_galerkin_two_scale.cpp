// The Galerkin basis's two-scale filters (radiometry/galerkin/TwoScale.h): push is exact (the
// child's function is the parent's, point for point, on ElementTree's own children), pull is the L2
// projection (against a fine rule over the piecewise function written out here), pull undoes push,
// and pull conserves power (the area-weighted mean) even on a trapezoid.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "radiometry/galerkin/Basis.h"
#include "radiometry/galerkin/Quadrature.h"
#include "radiometry/galerkin/TwoScale.h"
#include "radiometry/mesh/ElementTree.h"
#include "radiometry/scene/BuiltinScenes.h"

#include "tests/support/GalerkinElements.h"
#include "tests/support/Relative.h"

// A namespace of its own: unity builds put test files together, and no using-directive leaks out.
namespace radiant::galerkin::two_scale_tests {

using radiant::test::relativeTo;

namespace {

BasisCoefficients randomCoefficients(ElementShape shape, std::mt19937& random) {
    std::uniform_real_distribution<double> coefficient(-1, 1);
    BasisCoefficients c{};
    for (std::size_t k = 0; k < basisSize(shape); ++k) c[k] = coefficient(random);
    c[0] += 2;
    return c;
}

ElementParameter randomParameter(ElementShape shape, std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0, 1);
    double u = unit(random), v = unit(random);
    if (shape == ElementShape::Triangle && u + v > 1) u = 1 - u, v = 1 - v;
    return {u, v};
}

const PatchPolygon kElements[] = {test::tiltedSquare(), test::tiltedParallelogram(), test::tiltedTrapezoid(),
                                  test::tiltedTriangle()};

} // namespace

TEST_CASE("galerkin: childToParent is where ElementTree's split puts each child") {
    std::mt19937 random(3);
    for (const PatchPolygon& parent : kElements) {
        const ElementShape shape = shapeOf(parent);
        const std::array<PatchPolygon, 4> children = splitElementPolygon(parent);
        for (std::size_t c = 0; c < kChildCount; ++c)
            for (int sample = 0; sample < 10; ++sample) {
                const ElementParameter at = randomParameter(shape, random);
                const ElementParameter up = childToParent(shape, c, at);
                INFO("corners " << int(parent.count) << ", child " << c);
                CHECK(glm::length(test::mapOfCorners(children[c], at.u, at.v) - test::mapOfCorners(parent, up.u, up.v)) <
                      1e-14);
            }
    }
}

TEST_CASE("galerkin: ElementTree's children, by index, are the parameter pieces childToParent names") {
    // The solver will push and pull by child index (firstChild + c): the tree's own children must be
    // the pieces in the order TwoScale assumes, for the Cornell box's quads and triangles, two levels down.
    ElementTree tree(makeCornellBox());
    bool sawQuad = false, sawTriangle = false;
    const std::size_t rootCount = tree.roots().size();
    for (std::size_t r = 0; r < rootCount; ++r) {
        const ElementIndex root = tree.roots()[r];
        const ElementIndex first = tree.subdivide(root);
        tree.subdivide(first + 2);
    }
    for (ElementIndex e = 0; e < tree.size(); ++e) {
        if (tree.isLeaf(e)) continue;
        const PatchPolygon& parent = tree.polygon(e);
        const ElementShape shape = shapeOf(parent);
        (shape == ElementShape::Quad ? sawQuad : sawTriangle) = true;
        // Each child's corners at its own parameter corners, (0,0), (1,0), (1,1), (0,1) or (0,0), (1,0), (0,1).
        constexpr ElementParameter quadCorners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        constexpr ElementParameter triangleCorners[] = {{0, 0}, {1, 0}, {0, 1}};
        for (std::size_t c = 0; c < kChildCount; ++c) {
            const PatchPolygon& child = tree.polygon(tree.firstChild(e) + static_cast<ElementIndex>(c));
            for (std::size_t k = 0; k < child.count; ++k) {
                const ElementParameter corner = shape == ElementShape::Quad ? quadCorners[k] : triangleCorners[k];
                INFO("element " << e << ", child " << c << ", corner " << k);
                CHECK(glm::length(child.vertices[k] - pointAt(parent, childToParent(shape, c, corner))) <
                      1e-12 * std::sqrt(parent.area));
            }
        }
    }
    CHECK(sawQuad);
    CHECK(sawTriangle);
}

TEST_CASE("galerkin: push is exact: each child's function is the parent's, point for point") {
    std::mt19937 random(5);
    for (const PatchPolygon& parent : kElements) {
        const ElementShape shape = shapeOf(parent);
        const std::array<PatchPolygon, 4> children = splitElementPolygon(parent);
        for (int trial = 0; trial < 5; ++trial) {
            const BasisCoefficients p = randomCoefficients(shape, random);
            double power = 0;
            for (std::size_t c = 0; c < kChildCount; ++c) {
                const BasisCoefficients child = pushToChild(shape, p, c);
                for (int sample = 0; sample < 10; ++sample) {
                    const ElementParameter at = randomParameter(shape, random);
                    INFO("corners " << int(parent.count) << ", child " << c);
                    CHECK(valueAt(shape, child, at) == relativeTo(valueAt(shape, p, childToParent(shape, c, at)), 1e-12));
                }
                power += children[c].area * elementMean(children[c], child);
            }
            // The children together emit what the parent does (their areas and means by Basis.cpp).
            CHECK(power == relativeTo(parent.area * elementMean(parent, p), 1e-12));
        }
    }
}

TEST_CASE("galerkin: pull undoes push, and a constant pulls to itself") {
    std::mt19937 random(11);
    for (ElementShape shape : {ElementShape::Quad, ElementShape::Triangle}) {
        for (int trial = 0; trial < 10; ++trial) {
            const BasisCoefficients p = randomCoefficients(shape, random);
            std::array<BasisCoefficients, kChildCount> children{};
            for (std::size_t c = 0; c < kChildCount; ++c) children[c] = pushToChild(shape, p, c);
            const BasisCoefficients back = pullFromChildren(shape, children);
            for (std::size_t k = 0; k < kMaxBasisSize; ++k) CHECK(std::abs(back[k] - p[k]) < 1e-13 * std::abs(p[0]));
        }
        const BasisCoefficients constant{3.5, 0, 0, 0};
        const BasisCoefficients pulled = pullFromChildren(shape, {constant, constant, constant, constant});
        CHECK(pulled[0] == relativeTo(3.5, 1e-14));
        for (std::size_t k = 1; k < kMaxBasisSize; ++k) CHECK(std::abs(pulled[k]) < 1e-14);
    }
}

TEST_CASE("galerkin: pull is the L2 projection of the children's piecewise function") {
    // The piecewise function is written out here: on the square, the child is the quarter the
    // point is in, its own parameters 2u - offset; on the triangle, the corner children and the
    // medial one (u < 1/2, v < 1/2, u + v > 1/2) with the medial's parameters by inverting its
    // corners (1/2, 0), (1/2, 1/2), (0, 1/2). The projection is integrated by a 32 x 32 rule per
    // quarter of the square or per child of the triangle's collapsed rule on the whole (kinks on
    // the children's edges make a whole-element rule converge slowly, so the quad uses quarters).
    std::mt19937 random(13);
    for (int trial = 0; trial < 3; ++trial) {
        std::array<BasisCoefficients, kChildCount> quadChildren{}, triangleChildren{};
        for (auto& c : quadChildren) c = randomCoefficients(ElementShape::Quad, random);
        for (auto& c : triangleChildren) c = randomCoefficients(ElementShape::Triangle, random);

        BasisCoefficients quadExpected{};
        const QuadratureRule quarter = tensorGaussSquareRule(8);
        constexpr double offsetU[] = {0, 0.5, 0.5, 0}, offsetV[] = {0, 0, 0.5, 0.5};
        for (std::size_t c = 0; c < kChildCount; ++c)
            for (const QuadratureNode& node : quarter) {
                const ElementParameter parentAt{offsetU[c] + 0.5 * node.at.u, offsetV[c] + 0.5 * node.at.v};
                const double f = valueAt(ElementShape::Quad, quadChildren[c], node.at);
                const BasisCoefficients phi = basisValues(ElementShape::Quad, parentAt);
                for (std::size_t k = 0; k < 4; ++k) quadExpected[k] += 0.25 * node.weight * f * phi[k];
            }
        const BasisCoefficients quadPulled = pullFromChildren(ElementShape::Quad, quadChildren);
        for (std::size_t k = 0; k < 4; ++k) CHECK(std::abs(quadPulled[k] - quadExpected[k]) < 1e-13);

        // Triangle: each child's function in the parent's parameters by inverting its affine map,
        // given by the child's corners in the parent's parameters (ElementTree's split).
        struct Corners { double u0, v0, u1, v1, u2, v2; };
        constexpr Corners childCorners[] = {{0, 0, 0.5, 0, 0, 0.5}, {0.5, 0, 1, 0, 0.5, 0.5}, {0, 0.5, 0.5, 0.5, 0, 1},
                                            {0.5, 0, 0.5, 0.5, 0, 0.5}};
        const auto inChild = [&](std::size_t c, ElementParameter at, ElementParameter& local) {
            const Corners& k = childCorners[c];
            const double a = k.u1 - k.u0, b = k.u2 - k.u0, cc = k.v1 - k.v0, d = k.v2 - k.v0;
            const double det = a * d - b * cc, du = at.u - k.u0, dv = at.v - k.v0;
            local = {(d * du - b * dv) / det, (-cc * du + a * dv) / det};
            return local.u >= -1e-12 && local.v >= -1e-12 && local.u + local.v <= 1 + 1e-12;
        };
        BasisCoefficients triangleExpected{};
        const QuadratureRule childRule = collapsedGaussTriangleRule(8);
        for (std::size_t c = 0; c < kChildCount; ++c) {
            const Corners& k = childCorners[c];
            for (const QuadratureNode& node : childRule) {
                // A point of child c in the parent's parameters, from the child's corners.
                const ElementParameter parentAt{k.u0 + node.at.u * (k.u1 - k.u0) + node.at.v * (k.u2 - k.u0),
                                                k.v0 + node.at.u * (k.v1 - k.v0) + node.at.v * (k.v2 - k.v0)};
                ElementParameter local{};
                REQUIRE(inChild(c, parentAt, local));
                const double f = valueAt(ElementShape::Triangle, triangleChildren[c], local);
                const BasisCoefficients phi = basisValues(ElementShape::Triangle, parentAt);
                for (std::size_t m = 0; m < 3; ++m) triangleExpected[m] += 0.25 * node.weight * f * phi[m];
            }
        }
        const BasisCoefficients trianglePulled = pullFromChildren(ElementShape::Triangle, triangleChildren);
        for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(trianglePulled[k] - triangleExpected[k]) < 1e-13);
    }
}

TEST_CASE("galerkin: pull conserves power on every shape, the trapezoid included") {
    // The area-weighted mean of the pulled parent equals the children's power over the parent's
    // area, with the children's areas from ElementTree's split (unequal on a trapezoid).
    std::mt19937 random(17);
    for (const PatchPolygon& parent : kElements) {
        const ElementShape shape = shapeOf(parent);
        const std::array<PatchPolygon, 4> children = splitElementPolygon(parent);
        for (int trial = 0; trial < 5; ++trial) {
            std::array<BasisCoefficients, kChildCount> c{};
            double childPower = 0;
            for (std::size_t k = 0; k < kChildCount; ++k) {
                c[k] = randomCoefficients(shape, random);
                childPower += children[k].area * elementMean(children[k], c[k]);
            }
            INFO("corners " << int(parent.count) << ", child areas " << children[0].area << " " << children[1].area << " "
                            << children[2].area << " " << children[3].area);
            CHECK(parent.area * elementMean(parent, pullFromChildren(shape, c)) == relativeTo(childPower, 1e-12));
        }
    }
}

} // namespace radiant::galerkin::two_scale_tests
