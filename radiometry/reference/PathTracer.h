#pragma once
// The reference: the rendering equation for diffuse surfaces solved by Monte Carlo at one point,
// sharing nothing with the radiosity solvers but the scene and the ray caster. For a Lambertian
// surface L_r = rho E / pi, so the irradiance at x obeys
//
//   E(x) = integral over the hemisphere of L(y(w)) cos(theta) dw,   L(y) = (M(y) + rho(y) E(y)) / pi
//
// (Kajiya, "The Rendering Equation", SIGGRAPH 1986). One sample is one path. The emitted part is
// taken at every vertex two ways, combined by multiple importance sampling with the balance
// heuristic (Veach & Guibas, "Optimally Combining Sampling Techniques for Monte Carlo Rendering",
// SIGGRAPH 1995): next-event estimation from a point drawn on the emitters (area sampling,
// EmitterSampler.h), which is good for small or distant emitters, and the cosine-weighted direction
// that continues the path, which is good for emitters close by (the furnace's walls, a point beside
// a lamp), where area sampling alone has a variance that grows without bound. The cosine pdf cancels
// the integrand's cos/pi, so each bounce multiplies the path's weight by the reflectance it meets;
// Russian roulette ends paths without bias (Arvo & Kirk, "Particle Transport and Image Synthesis",
// SIGGRAPH 1990). Surfaces are one-sided: a ray that reaches a face's back gets nothing, and an
// emitter lights only its front. Punctual lights (points, spots, suns) cannot be hit by a ray: they
// enter only by next-event estimation, exactly, one shadow ray per light at every vertex
// (DirectLighting.h, which the solvers share only for their source term).
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/reference/EmitterSampler.h"
#include "radiometry/reference/RandomStream.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/sources/DirectLighting.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

class RayCaster;

class PathTracer {
public:
    /// Keeps references: the scene and the rays (built on the same scene) must outlive the tracer.
    PathTracer(const Scene& scene, const RayCaster& rays);

    /// One unbiased sample of E(x), W/m^2 per band, at x on a surface facing n (unit). x must lie on
    /// its face's plane exactly (ReferencePoint.h projects it there) so its own face never occludes.
    [[nodiscard]] Rgb sampleIrradiance(const glm::dvec3& x, const glm::dvec3& n, reference::RandomStream& random) const;

    [[nodiscard]] const Scene& scene() const { return scene_; }
    [[nodiscard]] const Rgb& reflectance(std::size_t surface) const { return reflectance_.at(surface); }
    [[nodiscard]] const Rgb& exitance(std::size_t surface) const { return exitance_.at(surface); }

private:
    /// Next-event estimation's share of the irradiance arriving at x straight from the emitters.
    [[nodiscard]] Rgb directIrradiance(const glm::dvec3& x, const glm::dvec3& n, reference::RandomStream& random) const;

    const Scene& scene_;
    const RayCaster& rays_;
    reference::EmitterSampler emitters_;
    DirectLighting lights_;
    std::vector<Rgb> reflectance_;  ///< per surface
    std::vector<Rgb> exitance_;     ///< per surface, W/m^2
};

} // namespace radiant
