#pragma once
// How a link's irradiance varies over its receiver, pushed down the element tree. Hanrahan, Salzman
// and Aupperle (1991) push each element's gathered irradiance to its descendants as a constant: a leaf
// under a coarse link gets that link's mean over the whole ancestor, which near contact or under the
// light is far from the leaf's own (leaf constants 20-40% off at the Cornell box's points). Each link
// already evaluates the exact kernel at the centroids of its receiver's four children-to-be (the
// refinement oracle's samples, HierarchicalFormFactor.h), so it carries the four children's means,
// and push-pull hands every child its own. Below that, on a quad, the four values are the nodes of a
// bilinear function over the element (in its bilinear parameters, nodes at 1/4 and 3/4), which gives
// each grandchild its value at the grandchild's centroid: a bilinear irradiance basis on the
// receiver, the role the higher-order bases play in wavelet radiosity (Gortler, Schroeder, Cohen,
// Hanrahan 1993). Every step keeps the mean: a child's four values average to the parent's value for
// that child, and the four children's average to the parent's mean, so energy is pushed exactly as
// before, only distributed within each ancestor.
#include <algorithm>
#include <array>
#include <cstddef>

#include <glm/common.hpp>

#include "radiometry/units/Quantity.h"

namespace radiant::hierarchical {

/// Irradiance values per element: one per child-to-be, in childCentroids' (and splitElementPolygon's)
/// order.
inline constexpr std::size_t kShapeValues = 4;

/// Adds to `child` (the four values of child number `index` of an element) what `parent` (that
/// element's four values) gives it: on a quad, the bilinear through the parent's values at the
/// child's own children's centroids, clamped at zero and rescaled to keep the child's mean; on a
/// triangle, the parent's value for that child, as a constant.
inline void addChildShape(const Rgb* parent, bool quad, std::size_t index, Rgb* child) {
    const Rgb& mean = parent[index];
    if (!quad) {
        for (std::size_t k = 0; k < kShapeValues; ++k) child[k] += mean;
        return;
    }
    // Children 0-3 cover the parameter quarters at (0, 0), (1/2, 0), (1/2, 1/2), (0, 1/2); the parent's
    // nodes sit at U, W in {0, 1} for u, w in {1/4, 3/4} (U = 2u - 1/2).
    static constexpr std::array<double, 4> offsetU{0, 1, 1, 0}, offsetW{0, 0, 1, 1};
    static constexpr std::array<double, 4> nodeU{-0.25, 0.25, 0.25, -0.25}, nodeW{-0.25, -0.25, 0.25, 0.25};
    std::array<Rgb, kShapeValues> values;
    Rgb sum(0.0);
    bool clamped = false;
    for (std::size_t k = 0; k < kShapeValues; ++k) {
        const double u = offsetU[index] + nodeU[k], w = offsetW[index] + nodeW[k];
        const Rgb v = (1 - u) * (1 - w) * parent[0] + u * (1 - w) * parent[1] + u * w * parent[2] + (1 - u) * w * parent[3];
        values[k] = glm::max(v, Rgb(0.0));
        clamped = clamped || values[k] != v;
        sum += values[k];
    }
    if (clamped)  // a steep kernel extrapolated below zero: keep the child's mean
        for (int band = 0; band < 3; ++band) {
            const double scale = sum[band] > 0 ? 4 * mean[band] / sum[band] : 0;
            for (std::size_t k = 0; k < kShapeValues; ++k) values[k][band] = sum[band] > 0 ? values[k][band] * scale : mean[band];
        }
    for (std::size_t k = 0; k < kShapeValues; ++k) child[k] += values[k];
}

} // namespace radiant::hierarchical
