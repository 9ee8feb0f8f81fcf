#pragma once
// The basis's two-scale filters between an element and the four children ElementTree gives it
// (Gortler, Schroeder, Cohen, Hanrahan, "Wavelet radiosity", SIGGRAPH 1993: push and pull as the
// multiwavelet filters; Zatz 1993's bases in a hierarchy).
//
// Children in the parent's parameters (Basis.h), matching splitElementPolygon's corner order:
//   quad:     0: [0, 1/2] x [0, 1/2], 1: [1/2, 1] x [0, 1/2], 2: [1/2, 1] x [1/2, 1], 3: [0, 1/2] x [1/2, 1],
//             each child's (u', v') running the same way as the parent's (u = offset + u'/2);
//   triangle: 0: corner v0 {v0, m01, m20}, 1: corner v1 {m01, v1, m12}, 2: corner v2 {m20, m12, v2},
//             3: the medial triangle {m01, m12, m20}, turned: (u, v) = (1/2 - v'/2, u'/2 + v'/2).
// A parent's polynomial restricted to a child is a polynomial of the same degree in the child's
// parameters (the child maps are affine in the parent's), so push is exact: the child's function is
// the parent's, point for point. Every child holds a quarter of the parent's parametric measure, so
// pull, the L2 projection of the children's piecewise function onto the parent's basis, is
//   parent = 1/4 sum_c P_c^T child_c   with P_c the push matrix of child c,
// and pull(push(p)) = p. On triangles and parallelograms this is the area-weighted projection; on
// a general planar quad it is the parametric one, which still conserves the area-weighted mean (the
// power) exactly because the area density is linear, inside the basis's span (Basis.h).
#include <array>
#include <cstddef>

#include "radiometry/galerkin/Basis.h"

namespace radiant::galerkin {

inline constexpr std::size_t kChildCount = 4;

/// Where child c's parameter point `at` lies in the parent's parameters.
[[nodiscard]] ElementParameter childToParent(ElementShape shape, std::size_t child, ElementParameter at);

/// The child's coefficients of the parent's function (exact).
[[nodiscard]] BasisCoefficients pushToChild(ElementShape shape, const BasisCoefficients& parent, std::size_t child);

/// The parent's coefficients of the children's piecewise function: its L2 projection (parametric
/// measure; the area measure on triangles and parallelograms).
[[nodiscard]] BasisCoefficients pullFromChildren(ElementShape shape, const std::array<BasisCoefficients, kChildCount>& children);

} // namespace radiant::galerkin
