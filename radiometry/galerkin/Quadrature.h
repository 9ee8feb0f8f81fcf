#pragma once
// Quadrature rules over an element's parameters (Basis.h), weights normalised to sum to 1 (the
// normalised parametric measure), for the coupling coefficients (Coupling.h) and for projecting
// functions onto the basis. Zatz (1993) computes the couplings by Gauss rules on each side; the
// coarse and fine rules here are the pairs a link would use (2 x 2 or 3 x 3 on a quad, 3 or 7 points
// on a triangle, of matching polynomial degree), and the n x n rules the tests' references.
#include <cstddef>
#include <vector>

#include "radiometry/galerkin/Basis.h"

namespace radiant::galerkin {

struct QuadratureNode {
    ElementParameter at;
    double weight = 0;  ///< share of the normalised parametric measure; a rule's weights sum to 1
};
using QuadratureRule = std::vector<QuadratureNode>;

/// n-point Gauss-Legendre on [0, 1] (nodes ascending, weights summing to 1), exact to degree 2n-1.
[[nodiscard]] QuadratureRule gaussLegendreOnUnitInterval(std::size_t n);  // v is unused (0)
/// n x n tensor Gauss on the unit square: exact for degree 2n-1 in each of u and v.
[[nodiscard]] QuadratureRule tensorGaussSquareRule(std::size_t n);
/// Strang and Fix's 3 interior points, weights 1/3: exact to total degree 2 (the 2 x 2 square rule's match).
[[nodiscard]] QuadratureRule triangleRule3();
/// Radon's 7 points: exact to total degree 5 (the 3 x 3 square rule's match).
[[nodiscard]] QuadratureRule triangleRule7();
/// n x n Gauss on the square collapsed onto the triangle (Duffy: u = s, v = (1 - s) t, weight
/// times 2 (1 - s)): exact to degree 2n-2 in total; the fine reference rule on triangles.
[[nodiscard]] QuadratureRule collapsedGaussTriangleRule(std::size_t n);

/// The rule of the given accuracy level for a shape: level 2 is 2 x 2 / 3 points, level 3 is
/// 3 x 3 / 7 points, larger levels n x n on a quad and the collapsed n x n on a triangle.
[[nodiscard]] QuadratureRule elementRule(ElementShape shape, std::size_t level);

/// The basis coefficients of f by the rule (c_k = sum_q w_q f(at_q) phi_k(at_q)): the L2 projection
/// in the parametric measure, exact when f times the basis is integrated exactly by the rule (for a
/// polynomial f of the basis's degree, elementRule level 2 on either shape).
template <class Function>
[[nodiscard]] BasisCoefficients projectOntoBasis(ElementShape shape, const QuadratureRule& rule, Function&& f) {
    BasisCoefficients c{};
    for (const QuadratureNode& node : rule) {
        const BasisCoefficients phi = basisValues(shape, node.at);
        const double value = node.weight * f(node.at);
        for (std::size_t k = 0; k < kMaxBasisSize; ++k) c[k] += value * phi[k];
    }
    return c;
}

} // namespace radiant::galerkin
