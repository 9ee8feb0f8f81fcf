#pragma once
// The Galerkin basis: an element's radiosity as a polynomial over the element, in an orthonormal
// basis, so that a link can carry how the light varies across its receiver and source instead of a
// constant (the hierarchical solver's constant elements miss that variation, which its per-patch
// final gather now makes up for at ~75% of the solve's time; docs/ARCHITECTURE.md, "Hierarchical").
//
//   H. R. Zatz, "Galerkin radiosity: a higher order solution method for global illumination",
//   SIGGRAPH 1993 (orthonormal Legendre bases on the elements, Gauss rules for the couplings);
//   S. J. Gortler, P. Schroeder, M. F. Cohen, P. Hanrahan, "Wavelet radiosity", SIGGRAPH 1993 (the
//   same bases in a hierarchy: push and pull as the two-scale filters of multiwavelets);
//   P. Bekaert, RenderPark (the peer: bilinear elements, 4 functions on a quad).
//
// Elements are ElementTree's (radiometry/mesh/ElementTree.h): planar quads parametrised by the
// bilinear map of their corners and triangles by the affine map of theirs,
//   quad:      x(u, v) = (1-u)(1-v) v0 + u(1-v) v1 + u v v2 + (1-u) v v3,   (u, v) in [0,1]^2,
//   triangle:  x(u, v) = v0 + u (v1 - v0) + v (v2 - v0),                     u, v >= 0, u + v <= 1.
// The basis lives in these parameters, orthonormal in the parametric measure normalised to 1
// (du dv on the square, 2 du dv on the triangle):
//   quad (tensor Legendre, 4):  1, sqrt3 (2u-1), sqrt3 (2v-1), 3 (2u-1)(2v-1);
//   triangle (linear, 3):       1, sqrt6 (2u+v-1), sqrt2 (3v-1)   [sqrt6 (l1-l0), sqrt2 (3 l2 - 1)
//                               in barycentrics: mean 0, variance 1, uncorrelated].
// On a triangle and on a parallelogram quad the area density is constant, so this is the normalised
// AREA measure and the basis is orthonormal in it. On a general planar quad (a trapezoid: the Cornell
// box's floor is one, to 0.6%) the area density J(u, v) / A is linear in u and v and the two
// measures differ by it; the parametric choice keeps the two-scale filters exact and the same for
// every element (ElementTree's children are the parent map restricted to the four parameter quarters),
// and since J is itself in the span of the basis, pull still conserves the area-weighted mean (the
// power) exactly (TwoScale.h). elementMean weights by J exactly.
#include <array>
#include <cstddef>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant::galerkin {

enum class ElementShape : unsigned char { Triangle, Quad };

/// Up to 4 coefficients; a triangle uses the first 3 and keeps the 4th at 0.
inline constexpr std::size_t kMaxBasisSize = 4;
using BasisCoefficients = std::array<double, kMaxBasisSize>;

/// A point in an element's parameters (see the maps above).
struct ElementParameter {
    double u = 0;
    double v = 0;
};

[[nodiscard]] constexpr std::size_t basisSize(ElementShape shape) { return shape == ElementShape::Quad ? 4 : 3; }
/// The shape of a PatchPolygon (count 3 or 4); other counts are a bug in the caller.
[[nodiscard]] ElementShape shapeOf(const PatchPolygon& element);

/// The values of all basis functions at (u, v) (a triangle's 4th is 0).
[[nodiscard]] BasisCoefficients basisValues(ElementShape shape, ElementParameter at);
/// sum_k c_k phi_k(u, v): the element's function at a point.
[[nodiscard]] double valueAt(ElementShape shape, const BasisCoefficients& coefficients, ElementParameter at);

/// x(u, v) on the element (the maps above).
[[nodiscard]] glm::dvec3 pointAt(const PatchPolygon& element, ElementParameter at);
/// dA / (A dmu): the area density relative to the normalised parametric measure mu (mean 1 over mu).
/// 1 on triangles and parallelograms; linear in u, v on a general planar quad.
[[nodiscard]] double areaDensity(const PatchPolygon& element, ElementParameter at);

/// The area-weighted mean of the element's function, (1/A) int f dA: c_0 on triangles and
/// parallelograms; on a general quad c_0 plus the linear terms' correlation with the area density
/// (exact, since the density is linear). Times A it is the element's radiant exitance integral.
[[nodiscard]] double elementMean(const PatchPolygon& element, const BasisCoefficients& coefficients);

} // namespace radiant::galerkin
