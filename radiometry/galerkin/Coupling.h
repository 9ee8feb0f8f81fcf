#pragma once
// A link's coupling coefficients in the Galerkin basis (Basis.h): how much of each of the source's
// basis functions' radiosity arrives as each of the receiver's basis functions' irradiance.
//
//   Zatz, "Galerkin radiosity: a higher order solution method for global illumination", SIGGRAPH 1993
//   (the coefficients by Gauss rules on both elements); Gortler, Schroeder, Cohen, Hanrahan, "Wavelet
//   radiosity", SIGGRAPH 1993 (the same in a hierarchy; their oracle compares these before and after a
//   split).
//
// Normalisation (the choice this header states):
//   K_ij = (1 / A_r) int_r int_s phi_i(x) G(x, y) V(x, y) phi_j(y) dA_y dA_x,
//   G(x, y) = max(0, cos theta_x) max(0, cos theta_y) / (pi r^2),
// with phi the basis functions of the receiver r (i) and the source s (j) in their own parameters.
// Then K_00 = F(r -> s), the form factor from receiver to source, and for a source radiosity
// B(y) = sum_j b_j phi_j(y) the irradiance H(x) = int_s G V B dA_y gathered over the receiver has the
// moments (1 / A_r) int_r phi_i H dA = sum_j K_ij b_j: the receiver's coefficients of H on triangles
// and parallelograms (orthonormal in the area measure there); on a general quad they differ from H's
// parametric coefficients by terms of the size of the area density's variation (Basis.h; 0.6% across
// the Cornell floor, halving with each split), which the Gram matrix of that linear density would
// remove exactly if a solver needs it. Reciprocity:
// A_r K_ij(r, s) = A_s K_ji(s, r), exactly, for the same rules.
//
// Quadrature: the integrand is smooth where the elements are far apart for their size; where they
// are close (r^2 / A small, adjacent elements sharing an edge above all) the 1 / r^2 kernel defeats a
// low-order rule, so the refinement oracle must split such links (the tests state each rule's error
// against the catalog's closed forms for ratios of distance to size).
#include <array>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/formfactor/PointKernel.h"
#include "radiometry/galerkin/Basis.h"
#include "radiometry/galerkin/Quadrature.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant::galerkin {

/// K[i][j]: receiver basis function i, source basis function j (a triangle's 4th row or column is 0).
using CouplingCoefficients = std::array<BasisCoefficients, kMaxBasisSize>;

/// One element's quadrature nodes in space, computed once per element and rule and shared by all of
/// its links: the points, their areas (rule weight x area density x element area, m^2, summing to
/// the area) and the basis values there.
struct ElementNodes {
    ElementShape shape = ElementShape::Quad;
    glm::dvec3 normal{0, 0, 1};
    double area = 0;
    std::vector<glm::dvec3> points;
    std::vector<double> areas;
    std::vector<BasisCoefficients> basis;
};

[[nodiscard]] ElementNodes elementNodes(const PatchPolygon& element, const QuadratureRule& rule);


/// K with a visibility per node pair, visible(receiverNode, sourceNode) in [0, 1]. The sum runs
/// receiver node by receiver node: first the source side's moments g_j = sum_q A_q G V phi_j(y_q),
/// then K_ij += A_p phi_i(x_p) g_j, so a pair costs one kernel and 4 multiply-adds.
template <class Visibility>
[[nodiscard]] CouplingCoefficients couplingCoefficients(const ElementNodes& receiver, const ElementNodes& source,
                                                        Visibility&& visible) {
    CouplingCoefficients k{};
    const std::size_t receiverSize = basisSize(receiver.shape), sourceSize = basisSize(source.shape);
    for (std::size_t p = 0; p < receiver.points.size(); ++p) {
        BasisCoefficients g{};
        for (std::size_t q = 0; q < source.points.size(); ++q) {
            const double kernel = pointToPointKernel(receiver.points[p], receiver.normal, source.points[q], source.normal);
            if (kernel == 0) continue;
            const double weight = source.areas[q] * kernel * visible(p, q);
            for (std::size_t j = 0; j < sourceSize; ++j) g[j] += weight * source.basis[q][j];
        }
        const double receiverWeight = receiver.areas[p] / receiver.area;
        for (std::size_t i = 0; i < receiverSize; ++i)
            for (std::size_t j = 0; j < sourceSize; ++j) k[i][j] += receiverWeight * receiver.basis[p][i] * g[j];
    }
    return k;
}

/// K without visibility (two elements that see each other whole).
[[nodiscard]] CouplingCoefficients couplingCoefficients(const ElementNodes& receiver, const ElementNodes& source);

/// The gathered irradiance's moments for a source radiosity with coefficients b: h_i = sum_j K_ij b_j.
[[nodiscard]] BasisCoefficients gatheredMoments(const CouplingCoefficients& k, const BasisCoefficients& sourceRadiosity);

} // namespace radiant::galerkin

namespace radiant::galerkin {

/// The column K_i0 (a constant source) with the inner integral exact: (1 / A_r) sum_p A_p phi_i(x_p)
/// F(dA_{x_p} -> source), F by Lambert's contour integral (radiometry/formfactor), so only the
/// receiver is sampled. For elements that touch or nearly touch (r^2 / A below ~1), where the
/// point-pair rules fail (the 1 / r^2 kernel: K_00 off by 51% (2 x 2) and 46% (3 x 3) for unit
/// rectangles sharing an edge) and this is within 0.18% / 0.002% there, 5.5% / 0.45% for unit squares
/// a quarter apart (test_galerkin_coupling.cpp). No visibility (the whole source seen).
[[nodiscard]] BasisCoefficients constantSourceMoments(const ElementNodes& receiver, const PatchPolygon& source);

} // namespace radiant::galerkin
