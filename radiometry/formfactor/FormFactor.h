#pragma once
// Form factors: the geometric kernel shared by every solver and by the probe.
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

class RayCaster;

/// Exact, unoccluded form factor from a differential area at x with unit normal n to a planar
/// polygon (Lambert's contour integral). The part of the polygon below x's tangent plane is clipped
/// away first; a polygon facing away from x (seen from its back) contributes nothing.
double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon);

struct FormFactorOptions {
    int visibilityRays = 16;     ///< stratified ray pairs for the visibility fraction (0 = unoccluded)
    std::uint64_t seed = 1;      ///< the stratified jitter is deterministic for a seed
    double accuracy = 1e-3;      ///< target relative error of the quadrature
};

/// F(from -> to): the fraction of the power leaving `from` that arrives at `to`. Quadrature over
/// `from` with the exact inner kernel to `to`; more points when the two are close for their size
/// (adjacent patches), so that all pairs reach options.accuracy. Times the visibility fraction from
/// stratified rays when `rays` is not null.
double formFactor(const PatchPolygon& from, const PatchPolygon& to, const RayCaster* rays,
                  const FormFactorOptions& options = {});

/// formFactor without visibility: the quadrature alone, to a relative `accuracy`.
double unoccludedFormFactor(const PatchPolygon& from, const PatchPolygon& to, double accuracy = 1e-3);

/// Fraction of the segments between `from` and `to` that are unblocked, from options.visibilityRays
/// stratified sample pairs on the parts of each in front of the other's plane, the parts that
/// exchange light (1 when rays is null, visibilityRays is 0 or the two do not face each other).
double visibilityFraction(const PatchPolygon& from, const PatchPolygon& to, const RayCaster* rays,
                          const FormFactorOptions& options = {});

} // namespace radiant
