#include "radiometry/galerkin/Basis.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "radiometry/common/Check.h"

namespace radiant::galerkin {

namespace {

const double kSqrt2 = std::sqrt(2.0);
const double kSqrt3 = std::sqrt(3.0);
const double kSqrt6 = std::sqrt(6.0);

/// |x_u x x_v| of the bilinear map: a x c + u a x e + v e x c with a = v1 - v0, c = v3 - v0,
/// e = v2 - v3 - v1 + v0, so linear in u and v for a planar quad (the uv term is e x e = 0).
double quadJacobian(const PatchPolygon& quad, ElementParameter at) {
    const auto& p = quad.vertices;
    const glm::dvec3 xu = (1 - at.v) * (p[1] - p[0]) + at.v * (p[2] - p[3]);
    const glm::dvec3 xv = (1 - at.u) * (p[3] - p[0]) + at.u * (p[2] - p[1]);
    return glm::length(glm::cross(xu, xv));
}

} // namespace

ElementShape shapeOf(const PatchPolygon& element) {
    // Elements are ElementTree's triangles and quads; anything else is a bug in the caller.
    if (element.count != 3 && element.count != 4)
        throw InvariantError(std::string(__FILE__) + ": shapeOf: an element with " + std::to_string(element.count) +
                             " corners (3 or 4 expected), area " + std::to_string(element.area) + " m^2");
    return element.count == 4 ? ElementShape::Quad : ElementShape::Triangle;
}

BasisCoefficients basisValues(ElementShape shape, ElementParameter at) {
    if (shape == ElementShape::Quad) {
        const double su = 2 * at.u - 1, sv = 2 * at.v - 1;
        return {1.0, kSqrt3 * su, kSqrt3 * sv, 3 * su * sv};
    }
    return {1.0, kSqrt6 * (2 * at.u + at.v - 1), kSqrt2 * (3 * at.v - 1), 0.0};
}

double valueAt(ElementShape shape, const BasisCoefficients& coefficients, ElementParameter at) {
    const BasisCoefficients phi = basisValues(shape, at);
    double sum = 0;
    for (std::size_t k = 0; k < kMaxBasisSize; ++k) sum += coefficients[k] * phi[k];
    return sum;
}

glm::dvec3 pointAt(const PatchPolygon& element, ElementParameter at) {
    const auto& p = element.vertices;
    if (element.count == 4)
        return (1 - at.u) * (1 - at.v) * p[0] + at.u * (1 - at.v) * p[1] + at.u * at.v * p[2] + (1 - at.u) * at.v * p[3];
    return p[0] + at.u * (p[1] - p[0]) + at.v * (p[2] - p[0]);
}

double areaDensity(const PatchPolygon& element, ElementParameter at) {
    if (element.count != 4) return 1.0;
    // J is linear, so its mean over the square is its value at the centre.
    return quadJacobian(element, at) / quadJacobian(element, {0.5, 0.5});
}

double elementMean(const PatchPolygon& element, const BasisCoefficients& coefficients) {
    if (element.count != 4) return coefficients[0];
    // density = 1 + alpha (2u-1) + beta (2v-1) = 1 + (alpha/sqrt3) phi_1 + (beta/sqrt3) phi_2, so by
    // orthonormality int f density dmu = c_0 + c_1 alpha/sqrt3 + c_2 beta/sqrt3.
    const double alpha = 0.5 * (areaDensity(element, {1, 0.5}) - areaDensity(element, {0, 0.5}));
    const double beta = 0.5 * (areaDensity(element, {0.5, 1}) - areaDensity(element, {0.5, 0}));
    return coefficients[0] + (coefficients[1] * alpha + coefficients[2] * beta) / kSqrt3;
}

} // namespace radiant::galerkin
