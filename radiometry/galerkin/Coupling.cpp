#include "radiometry/galerkin/Coupling.h"

#include "radiometry/formfactor/FormFactor.h"

namespace radiant::galerkin {

ElementNodes elementNodes(const PatchPolygon& element, const QuadratureRule& rule) {
    ElementNodes nodes;
    nodes.shape = shapeOf(element);
    nodes.normal = element.normal;
    nodes.area = element.area;
    nodes.points.reserve(rule.size());
    nodes.areas.reserve(rule.size());
    nodes.basis.reserve(rule.size());
    for (const QuadratureNode& node : rule) {
        nodes.points.push_back(pointAt(element, node.at));
        nodes.areas.push_back(node.weight * areaDensity(element, node.at) * element.area);
        nodes.basis.push_back(basisValues(nodes.shape, node.at));
    }
    return nodes;
}

CouplingCoefficients couplingCoefficients(const ElementNodes& receiver, const ElementNodes& source) {
    return couplingCoefficients(receiver, source, [](std::size_t, std::size_t) { return 1.0; });
}

BasisCoefficients gatheredMoments(const CouplingCoefficients& k, const BasisCoefficients& sourceRadiosity) {
    BasisCoefficients h{};
    for (std::size_t i = 0; i < kMaxBasisSize; ++i)
        for (std::size_t j = 0; j < kMaxBasisSize; ++j) h[i] += k[i][j] * sourceRadiosity[j];
    return h;
}

BasisCoefficients constantSourceMoments(const ElementNodes& receiver, const PatchPolygon& source) {
    BasisCoefficients moments{};
    const std::size_t size = basisSize(receiver.shape);
    for (std::size_t p = 0; p < receiver.points.size(); ++p) {
        const double weight =
            receiver.areas[p] / receiver.area * pointToPolygonFormFactor(receiver.points[p], receiver.normal, source.corners());
        for (std::size_t i = 0; i < size; ++i) moments[i] += weight * receiver.basis[p][i];
    }
    return moments;
}

} // namespace radiant::galerkin
