#include "radiometry/reference/PathTracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"

namespace radiant {
namespace {

/// A cosine-distributed direction about the unit normal n (Malley's method: a uniform point on the
/// unit disk lifted to the hemisphere), in an orthonormal basis from Duff et al., "Building an
/// Orthonormal Basis, Revisited" (JCGT 2017).
glm::dvec3 cosineDirection(const glm::dvec3& n, double u, double v) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    const glm::dvec3 tangent(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::dvec3 bitangent(b, sign + n.y * n.y * a, -n.y);
    const double radius = std::sqrt(u);
    const double phi = 2 * std::numbers::pi * v;
    return radius * std::cos(phi) * tangent + radius * std::sin(phi) * bitangent + std::sqrt(std::max(0.0, 1 - u)) * n;
}

double largestBand(const Rgb& v) { return std::max({v.x, v.y, v.z}); }

} // namespace

PathTracer::PathTracer(const Scene& scene, const RayCaster& rays) : scene_(scene), rays_(rays), emitters_(scene), lights_(scene, &rays) {
    reflectance_.reserve(scene.surfaces.size());
    exitance_.reserve(scene.surfaces.size());
    for (const Surface& surface : scene.surfaces) {
        const Material& material = scene.materials.at(surface.material);
        reflectance_.push_back(material.reflectance);
        exitance_.push_back(material.exitance.value());
    }
}

Rgb PathTracer::directIrradiance(const glm::dvec3& x, const glm::dvec3& n, reference::RandomStream& random) const {
    // A delta light has one direction: its next event is exact and no cosine sample can find it.
    const Rgb punctual = lights_.empty() ? Rgb(0.0) : lights_.at(x, n).value();
    if (emitters_.empty()) return punctual;
    const double choose = random.uniform(), u = random.uniform(), v = random.uniform();
    const reference::EmitterSample light = emitters_.sample(choose, u, v);
    const glm::dvec3 d = light.point - x;
    const double r2 = glm::dot(d, d);
    if (!(r2 > 0)) return punctual;
    const double r = std::sqrt(r2);
    const double cosX = glm::dot(n, d) / r;
    const double cosY = -glm::dot(light.normal, d) / r;
    if (cosX <= 0 || cosY <= 0) return punctual;
    if (rays_.occluded(x, light.point)) return punctual;
    // L = M / pi from the emitter, times the geometry term, over the density of the point, times
    // the balance heuristic's weight against the cosine sampling of the same direction.
    const double lightPdf = r2 / (cosY * light.inverseDensity);  // per steradian
    const double cosinePdf = cosX / std::numbers::pi;
    const double misWeight = lightPdf / (lightPdf + cosinePdf);
    return punctual + light.exitance * (cosX * cosY / (std::numbers::pi * r2) * light.inverseDensity * misWeight);
}

Rgb PathTracer::sampleIrradiance(const glm::dvec3& x, const glm::dvec3& n, reference::RandomStream& random) const {
    Rgb irradiance = directIrradiance(x, n, random);
    Rgb weight(1.0);
    glm::dvec3 origin = x, normal = n;
    for (;;) {
        const double u = random.uniform(), v = random.uniform();
        const glm::dvec3 direction = cosineDirection(normal, u, v);
        const std::optional<RayHit> hit = rays_.intersect(origin, direction);
        if (!hit) break;                                  // escaped an open scene
        const double cosY = -glm::dot(hit->normal, direction);
        if (cosY <= 0) break;  // a face's back neither reflects nor emits
        const Rgb& emitted = exitance_[hit->surface];
        if (emitted != Rgb(0.0)) {
            // The cosine-sampled direction found an emitter: its share pi L cos / p = M (the
            // pdf cos/pi cancels), weighted against next-event estimation's density for the point.
            const double cosinePdf = glm::dot(normal, direction) / std::numbers::pi;
            const double lightPdf = emitters_.density(emitted) * hit->distance * hit->distance / cosY;
            irradiance += weight * emitted * (cosinePdf / (cosinePdf + lightPdf));
        }
        // Onto the face's plane in double: the ray caster ignores the plane a ray starts (or ends) on
        // only when the point lies on it, and a grazing hit's distance may keep float's rounding.
        const Face& face = scene_.surfaces[hit->surface].faces[hit->face];
        origin = hit->point - glm::dot(face.normal, hit->point - face.vertices[0]) * face.normal;
        normal = hit->normal;
        weight *= reflectance_[hit->surface];
        irradiance += weight * directIrradiance(origin, normal, random);
        // Survive with probability q (the largest band of the weight, at most 1) and divide the
        // weight by q: the expected contribution of what follows is unchanged.
        const double survive = std::min(1.0, largestBand(weight));
        if (!(survive > 0) || random.uniform() >= survive) break;
        weight /= survive;
    }
    return irradiance;
}

} // namespace radiant
