#include "radiometry/galerkin/TwoScale.h"

#include "radiometry/common/Check.h"
#include "radiometry/galerkin/Quadrature.h"

namespace radiant::galerkin {

namespace {

/// pushMatrix[c][l][k] = <phi_l of child c, phi_k of the parent restricted to c>, the child's l-th
/// coefficient per unit of the parent's k-th. Computed once by a rule exact for the products
/// (degree 2 in each of u and v on a quad, total degree 2 on a triangle; 3 x 3 Gauss and Radon's 7 are
/// exact to 5).
using PushMatrices = std::array<std::array<BasisCoefficients, kMaxBasisSize>, kChildCount>;

PushMatrices computePushMatrices(ElementShape shape) {
    const QuadratureRule rule = elementRule(shape, 3);
    PushMatrices matrices{};
    for (std::size_t c = 0; c < kChildCount; ++c)
        for (std::size_t k = 0; k < basisSize(shape); ++k) {
            const BasisCoefficients column = projectOntoBasis(shape, rule, [&](ElementParameter at) {
                return basisValues(shape, childToParent(shape, c, at))[k];
            });
            for (std::size_t l = 0; l < basisSize(shape); ++l) matrices[c][l][k] = column[l];
        }
    return matrices;
}

const PushMatrices& pushMatrices(ElementShape shape) {
    static const PushMatrices quad = computePushMatrices(ElementShape::Quad);
    static const PushMatrices triangle = computePushMatrices(ElementShape::Triangle);
    return shape == ElementShape::Quad ? quad : triangle;
}

} // namespace

ElementParameter childToParent(ElementShape shape, std::size_t child, ElementParameter at) {
    RADIANT_CHECK_LT(child, kChildCount);
    const double u = 0.5 * at.u, v = 0.5 * at.v;
    if (shape == ElementShape::Quad) {
        constexpr std::array<ElementParameter, kChildCount> offset{{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}};
        return {offset[child].u + u, offset[child].v + v};
    }
    switch (child) {
    case 0: return {u, v};
    case 1: return {0.5 + u, v};
    case 2: return {u, 0.5 + v};
    default: return {0.5 - v, u + v};  // medial: corners m01, m12, m20 at (1/2, 0), (1/2, 1/2), (0, 1/2)
    }
}

BasisCoefficients pushToChild(ElementShape shape, const BasisCoefficients& parent, std::size_t child) {
    RADIANT_CHECK_LT(child, kChildCount);
    const auto& matrix = pushMatrices(shape)[child];
    BasisCoefficients result{};
    for (std::size_t l = 0; l < basisSize(shape); ++l)
        for (std::size_t k = 0; k < basisSize(shape); ++k) result[l] += matrix[l][k] * parent[k];
    return result;
}

BasisCoefficients pullFromChildren(ElementShape shape, const std::array<BasisCoefficients, kChildCount>& children) {
    const PushMatrices& matrices = pushMatrices(shape);
    BasisCoefficients result{};
    for (std::size_t c = 0; c < kChildCount; ++c)
        for (std::size_t l = 0; l < basisSize(shape); ++l)
            for (std::size_t k = 0; k < basisSize(shape); ++k) result[k] += 0.25 * matrices[c][l][k] * children[c][l];
    return result;
}

} // namespace radiant::galerkin
