#include "radiometry/probe/Probe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/common/Check.h"
#include "radiometry/common/Error.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/ConvexFan.h"
#include "radiometry/probe/ChordError.h"
#include "radiometry/probe/PolygonSamples.h"
#include "radiometry/probe/RadiosityInterpolation.h"
#include "radiometry/solidangle/PolygonSolidAngle.h"
#include "radiometry/sources/DiffuseEmitter.h"

namespace radiant {

namespace {

std::string formatPoint(const glm::dvec3& p) {
    std::ostringstream out;
    out.precision(6);
    out << p.x << "," << p.y << "," << p.z;
    return out.str();
}

/// How far x lies outside a convex planar face, measured in its plane (<= 0 inside).
double distanceOutsideFace(const Face& face, const glm::dvec3& x) {
    double outside = std::numeric_limits<double>::lowest();
    const std::size_t count = face.vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& a = face.vertices[i];
        const glm::dvec3& b = face.vertices[(i + 1) % count];
        const glm::dvec3 inward = glm::cross(face.normal, b - a);
        const double length = glm::length(inward);
        if (length > 0) outside = std::max(outside, -glm::dot(x - a, inward) / length);
    }
    return outside;
}

/// The point of segment ab nearest to x.
glm::dvec3 nearestOnSegment(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& x) {
    const glm::dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    if (!(length2 > 0)) return a;
    return a + std::clamp(glm::dot(x - a, ab) / length2, 0.0, 1.0) * ab;
}

/// The point of a convex planar face nearest to x: x's projection when it falls inside, else the
/// nearest point of its boundary.
glm::dvec3 nearestOnFace(const Face& face, const glm::dvec3& x) {
    const glm::dvec3 projected = x - glm::dot(face.normal, x - face.vertices[0]) * face.normal;
    if (distanceOutsideFace(face, projected) <= 0) return projected;
    glm::dvec3 best = face.vertices[0];
    double bestDistance = std::numeric_limits<double>::infinity();
    const std::size_t count = face.vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 p = nearestOnSegment(face.vertices[i], face.vertices[(i + 1) % count], x);
        const double d = glm::length(p - x);
        if (d < bestDistance) {
            bestDistance = d;
            best = p;
        }
    }
    return best;
}

/// Visible fractions of a polygon seen from x with normal n, from stratified sample points, each
/// ray weighted by the kernel whose integral it corrects.
struct VisibleFractions {
    double solidAngle = 1;  ///< weights |cos_y| / r^2 dA
    double formFactor = 1;  ///< weights cos_x cos_y / r^2 dA, front side only
    double projected = 1;   ///< weights cos_x |cos_y| / r^2 dA, either side
    /// The form factor's visible first moment about the polygon's centroid, over its whole weight:
    /// sum_visible w (p - c) / sum_all w, so that a radiosity B + g.(p - c) across the polygon
    /// contributes F (B formFactor + g.formFactorMoment).
    glm::dvec3 formFactorMoment{0.0};
};

/// `sampleWeights`, when given, gets each sample's share of the form factor where it is visible (0
/// where blocked or behind), over the whole unoccluded weight: they sum to VisibleFractions::formFactor.
VisibleFractions visibleFractions(const glm::dvec3& x, const glm::dvec3& n, const PatchPolygon& polygon,
                                  const RayCaster& rays, int perSide, std::uint64_t seed,
                                  std::vector<PolygonSample>& samples, std::vector<double>* sampleWeights = nullptr) {
    stratifiedPolygonSamples(polygon, perSide, seed, samples);
    if (sampleWeights) sampleWeights->assign(samples.size(), 0.0);
    double solidAngleAll = 0, solidAngleVisible = 0, formFactorAll = 0, formFactorVisible = 0;
    double projectedAll = 0, projectedVisible = 0;
    glm::dvec3 momentVisible(0.0);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const PolygonSample& s = samples[i];
        const glm::dvec3 d = s.point - x;
        const double r2 = glm::dot(d, d);
        if (!(r2 > 0)) continue;
        const double r = std::sqrt(r2);
        const double cosX = glm::dot(n, d) / r;
        if (cosX <= 0) continue;  // below x's horizon: x cannot see it at all
        const double cosY = -glm::dot(polygon.normal, d) / r;
        const double wSolidAngle = s.area * std::abs(cosY) / r2;
        const double wFormFactor = s.area * cosX * std::max(0.0, cosY) / r2;
        const double wProjected = s.area * cosX * std::abs(cosY) / r2;
        if (wSolidAngle <= 0 && wFormFactor <= 0) continue;
        const bool visible = !rays.occluded(x, s.point);
        solidAngleAll += wSolidAngle;
        formFactorAll += wFormFactor;
        projectedAll += wProjected;
        if (visible) {
            solidAngleVisible += wSolidAngle;
            formFactorVisible += wFormFactor;
            projectedVisible += wProjected;
            momentVisible += wFormFactor * (s.point - polygon.centroid);
            if (sampleWeights) (*sampleWeights)[i] = wFormFactor;
        }
    }
    if (sampleWeights)
        for (double& w : *sampleWeights) w = formFactorAll > 0 ? w / formFactorAll : 0.0;
    VisibleFractions f;
    if (solidAngleAll > 0) f.solidAngle = solidAngleVisible / solidAngleAll;
    if (formFactorAll > 0) {
        f.formFactor = formFactorVisible / formFactorAll;
        f.formFactorMoment = momentVisible / formFactorAll;
    }
    if (projectedAll > 0) f.projected = projectedVisible / projectedAll;
    return f;
}

/// Patch j's radiosity slope per band in its plane (W/m^2 per m): weighted least squares, weights
/// 1 / d^2, over its neighbours' centroids and values, then limited (Barth & Jespersen, "The design
/// and application of upwind schemes on unstructured meshes", AIAA 89-0366) so that B_j + g.(v - c_j)
/// at each of j's corners v inside the face stays within the range of j's and its neighbours' values,
/// and at a corner on the face's edge stays non-negative: the patch's mean is kept (a slope
/// integrates to zero over the patch about its centroid), no inner corner is made brighter or darker
/// than the patches round it, and a row along an edge (the floor's open front in a block's shadow,
/// a contact line) keeps the slope its neighbours show instead of being flattened for want of a
/// neighbour beyond it (session 20: the axis-aligned box's shadowed face 5 cm up, Gauss-Seidel,
/// +3.0 / +3.3 / +4.7% with the range limit there too, +2.2 / +2.5 / +3.5% with this).
std::array<glm::dvec3, 3> radiositySlope(const PatchMesh& mesh, std::span<const Rgb> radiosity, std::size_t j,
                                         std::span<const std::uint32_t> neighbours) {
    std::array<glm::dvec3, 3> g{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    if (neighbours.size() < 2) return g;
    const Patch& p = mesh.patches[j];
    // An orthonormal pair in the patch's plane.
    const glm::dvec3 helper = std::abs(p.normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(p.normal, helper));
    const glm::dvec3 t2 = glm::cross(p.normal, t1);
    double aa = 0, ab = 0, bb = 0;
    glm::dvec3 ra(0.0), rb(0.0);
    Rgb lo = radiosity[j], hi = radiosity[j];
    for (const std::uint32_t k : neighbours) {
        const glm::dvec3 d = mesh.patches[k].centroid - p.centroid;
        const double d2 = glm::dot(d, d);
        if (!(d2 > 0)) continue;
        const double a = glm::dot(d, t1), b = glm::dot(d, t2), w = 1.0 / d2;
        const Rgb db = radiosity[k] - radiosity[j];
        aa += w * a * a;
        ab += w * a * b;
        bb += w * b * b;
        ra += w * a * db;
        rb += w * b * db;
        lo = glm::min(lo, radiosity[k]);
        hi = glm::max(hi, radiosity[k]);
    }
    // A corner inside the face (the patches round it close its angle, 2 pi) is limited to the range
    // round it; a corner on the face's edge (the open front, a contact line) has nothing beyond it to
    // bound the slope but positivity.
    std::array<bool, 4> interior{};
    for (std::uint8_t k = 0; k < p.cornerCount; ++k) {
        const std::uint32_t v = p.corners[k];
        const auto angleAt = [&](const Patch& q) {
            for (std::uint8_t i = 0; i < q.cornerCount; ++i)
                if (q.corners[i] == v) {
                    const glm::dvec3 a = mesh.vertices[q.corners[(i + 1) % q.cornerCount]] - mesh.vertices[v];
                    const glm::dvec3 b = mesh.vertices[q.corners[(i + q.cornerCount - 1) % q.cornerCount]] - mesh.vertices[v];
                    return std::acos(std::clamp(glm::dot(a, b) / (glm::length(a) * glm::length(b)), -1.0, 1.0));
                }
            return 0.0;
        };
        double angle = angleAt(p);
        for (const std::uint32_t q : neighbours) angle += angleAt(mesh.patches[q]);
        interior[k] = angle > 2 * std::numbers::pi - 1e-6;
    }
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-9 * (aa + bb) * (aa + bb))) return g;  // neighbours along one line: no slope across it
    for (int c = 0; c < 3; ++c) {
        const double ga = (bb * ra[c] - ab * rb[c]) / det, gb = (aa * rb[c] - ab * ra[c]) / det;
        glm::dvec3 slope = ga * t1 + gb * t2;
        double limit = 1;
        for (std::uint8_t k = 0; k < p.cornerCount; ++k) {
            const double delta = glm::dot(slope, mesh.vertices[p.corners[k]] - p.centroid);
            if (!interior[k]) {
                if (delta < 0) limit = std::min(limit, -radiosity[j][c] / delta);
                continue;
            }
            if (delta > 0) limit = std::min(limit, (hi[c] - radiosity[j][c]) / delta);
            else if (delta < 0) limit = std::min(limit, (lo[c] - radiosity[j][c]) / delta);
        }
        g[c] = slope * std::max(0.0, limit);
    }
    return g;
}

/// gatherDirect reads a patch's direct light point by point where the squared distance from x to
/// its centroid is under this many times its area: nearer, x's kernel weighs one side of it more.
constexpr double kDirectNearDistanceSquaredOverArea = 25;
/// gatherDirect traces the emitters' light only in scenes with at most this many emitting faces
/// (after fanning into quads and triangles); the punctual lights always.
constexpr std::size_t kMaxTracedEmitterFaces = 16;
/// A patch whose coarse visible share differs from a neighbour's by more than this is sampled again.
constexpr double kNeighbourShareGap = 0.25;

glm::dvec3 unitNormal(const glm::dvec3& n) {
    const double length = glm::length(n);
    if (!(length > 0) || !std::isfinite(length))
        throw RadiantError({"", "probe normal"}, "the normal (" + formatPoint(n) + ") must be a finite non-zero vector");
    return n / length;
}

} // namespace

Probe::Probe(const Scene& scene, const PatchMesh& mesh, const RayCaster* rays, const ProbeOptions& options)
    : scene_(scene), mesh_(mesh), rays_(rays), options_(options), locator_(mesh), lighting_(scene, rays) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& v : mesh.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    if (!mesh.vertices.empty()) sceneSize_ = std::max(glm::length(hi - lo), 1e-9);
    for (const Surface& surface : scene.surfaces) {
        const Material& material = scene.materials.at(surface.material);
        if (!material.emits()) continue;
        for (const Face& face : surface.faces)
            detail::forEachFanPiece(face.vertices.size(), [&](std::size_t first, std::size_t count) {
                std::array<glm::dvec3, 4> corners{face.vertices[0]};
                for (std::size_t i = 1; i < count; ++i) corners[i] = face.vertices[first + i - 1];
                const PatchPolygon polygon = PatchPolygon::from(std::span<const glm::dvec3>(corners.data(), count));
                if (polygon.area > 0) emitters_.push_back({polygon, material.exitance.value()});
            });
    }
    // Every gather point of a near patch casts rays to every emitting face: a lamp made of many
    // triangles would make a reading take seconds. Its light then stays in the part read by the
    // neighbours' slope, as all of it was before (the split is consistent whichever sources are traced).
    if (emitters_.size() > kMaxTracedEmitterFaces) emitters_.clear();
    // Neighbours for the gather's slopes: patches of one surface and face sharing a corner (the mesh
    // is conforming within a face, so these are the ones all round it).
    std::vector<std::uint32_t> vertexFirst(mesh.vertices.size() + 1, 0), vertexPatches;
    for (const Patch& p : mesh.patches)
        for (std::uint8_t k = 0; k < p.cornerCount; ++k) ++vertexFirst[p.corners[k] + 1];
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) vertexFirst[v + 1] += vertexFirst[v];
    vertexPatches.resize(vertexFirst.back());
    {
        std::vector<std::uint32_t> fill(vertexFirst.begin(), vertexFirst.end() - 1);
        for (std::uint32_t j = 0; j < mesh.patches.size(); ++j)
            for (std::uint8_t k = 0; k < mesh.patches[j].cornerCount; ++k)
                vertexPatches[fill[mesh.patches[j].corners[k]]++] = j;
    }
    neighbourFirst_.assign(1, 0);
    neighbourFirst_.reserve(mesh.patches.size() + 1);
    for (std::uint32_t j = 0; j < mesh.patches.size(); ++j) {
        const Patch& p = mesh.patches[j];
        const std::size_t first = neighbours_.size();
        for (std::uint8_t k = 0; k < p.cornerCount; ++k)
            for (std::uint32_t i = vertexFirst[p.corners[k]]; i < vertexFirst[p.corners[k] + 1]; ++i) {
                const std::uint32_t q = vertexPatches[i];
                if (q == j || mesh.patches[q].surface != p.surface || mesh.patches[q].face != p.face) continue;
                if (std::find(neighbours_.begin() + static_cast<std::ptrdiff_t>(first), neighbours_.end(), q) ==
                    neighbours_.end())
                    neighbours_.push_back(q);
            }
        neighbourFirst_.push_back(static_cast<std::uint32_t>(neighbours_.size()));
    }
}

std::optional<SurfaceSnap> Probe::snapOntoSurface(const glm::dvec3& x, double maxDistance) const {
    const double tolerance = options_.onSurfaceTolerance * sceneSize_;
    for (const Surface& surface : scene_.surfaces)
        for (const Face& face : surface.faces) {
            if (face.vertices.size() < 3) continue;
            const double height = glm::dot(face.normal, x - face.vertices[0]);
            if (std::abs(height) <= tolerance && std::max(0.0, distanceOutsideFace(face, x)) <= tolerance)
                return std::nullopt;  // locate takes it as it is
        }
    // Off every face: a curved surface's facet takes a point within its chord error (plus the
    // on-surface tolerance), whatever maxDistance, for the smooth surface lies that far off it.
    const std::vector<std::vector<double>> chordErrors = tessellationChordErrors(scene_);
    std::optional<SurfaceSnap> nearest;
    for (std::uint32_t s = 0; s < scene_.surfaces.size(); ++s) {
        const std::vector<Face>& faces = scene_.surfaces[s].faces;
        for (std::size_t f = 0; f < faces.size(); ++f) {
            if (faces[f].vertices.size() < 3) continue;
            const glm::dvec3 p = nearestOnFace(faces[f], x);
            const double distance = glm::length(p - x);
            const double chordError = chordErrors[s][f];
            const bool curved = distance > maxDistance && distance <= chordError + tolerance;
            if ((distance <= maxDistance || curved) && (!nearest || distance < nearest->distance))
                nearest = SurfaceSnap{p, distance, s, curved ? chordError : 0.0};
        }
    }
    return nearest;
}

SurfacePoint Probe::locate(const glm::dvec3& x, const glm::dvec3& n) const {
    const glm::dvec3 up = unitNormal(n);
    const double tolerance = options_.onSurfaceTolerance * sceneSize_;
    std::optional<SurfacePoint> best;
    double bestAlignment = -2;
    std::string nearestName;
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (std::uint32_t s = 0; s < scene_.surfaces.size(); ++s) {
        const Surface& surface = scene_.surfaces[s];
        for (std::uint32_t f = 0; f < surface.faces.size(); ++f) {
            const Face& face = surface.faces[f];
            if (face.vertices.size() < 3) continue;
            const double height = glm::dot(face.normal, x - face.vertices[0]);
            const double outside = std::max(0.0, distanceOutsideFace(face, x));
            const double distance = std::hypot(height, outside);
            if (distance < nearestDistance) {
                nearestDistance = distance;
                nearestName = surface.name;
            }
            if (std::abs(height) > tolerance || outside > tolerance) continue;
            const double alignment = glm::dot(face.normal, up);
            if (alignment > bestAlignment) {
                bestAlignment = alignment;
                best = SurfacePoint{s, f, 0, x - height * face.normal};
            }
        }
    }
    if (!best) {
        std::ostringstream message;
        message << "the point (" << formatPoint(x) << ") lies on no surface";
        if (!nearestName.empty()) message << " (nearest: '" << nearestName << "', " << nearestDistance << " m away)";
        throw RadiantError({scene_.name, "probe point"}, message.str());
    }
    if (bestAlignment <= 0)
        throw RadiantError({scene_.name, "probe normal"},
                           "the normal (" + formatPoint(n) + ") points into surface '" +
                               scene_.surfaces[best->surface].name + "' at (" + formatPoint(x) + ")");
    best->patch = locator_.find(best->surface, best->face, best->point);
    if (best->patch == PatchLocator::npos)
        throw RadiantError({scene_.name, "probe point"}, "surface '" + scene_.surfaces[best->surface].name +
                                                         "' has no patches at (" + formatPoint(x) + ")");
    return *best;
}

ProbeReading Probe::measure(const glm::dvec3& x, const glm::dvec3& n, std::span<const Rgb> radiosity,
                            std::optional<std::size_t> targetSurface) const {
    return measure(locate(x, n), n, radiosity, targetSurface);
}

ProbeReading Probe::measure(const SurfacePoint& at, const glm::dvec3& n, std::span<const Rgb> radiosity,
                            std::optional<std::size_t> targetSurface) const {
    ProbeReading reading;
    reading.at = at;
    reading.normal = unitNormal(n);
    reading.interpolatedRadiosity = RadiosityRgb(interpolateRadiosity(mesh_, radiosity, at.patch, at.point));
    reading.patchRadiosity = RadiosityRgb(radiosity[at.patch]);
    reading.irradiance = irradiance(at, reading.normal, radiosity);
    reading.directIrradiance = lighting_.at(at.point, reading.normal);
    const Material& material = scene_.materials.at(scene_.surfaces.at(at.surface).material);
    reading.radiosity = RadiosityRgb(material.exitance.value() + material.reflectance * reading.irradiance.value());
    reading.radiance = radianceFromRadiosity(reading.radiosity);
    if (targetSurface) reading.target = target(at, reading.normal, *targetSurface);
    return reading;
}

Rgb Probe::directAt(const glm::dvec3& y, const glm::dvec3& n, std::uint64_t seed, std::vector<PolygonSample>& scratch) const {
    Rgb e = lighting_.at(y, n).value();
    for (std::size_t k = 0; k < emitters_.size(); ++k) {
        const Emitter& emitter = emitters_[k];
        const double f = pointToPolygonFormFactor(y, n, emitter.polygon.corners());
        if (f <= 0) continue;
        const VisibleFractions visible = visibleFractions(y, n, emitter.polygon, *rays_, options_.directRaysPerSide,
                                                          mixBits(seed ^ mixBits(k + 1)), scratch);
        e += emitter.exitance * (f * visible.formFactor);
    }
    return e;
}

Rgb Probe::directOverSamples(std::size_t j, std::vector<Rgb>& atSamples, std::vector<PolygonSample>& points,
                             std::vector<PolygonSample>& scratch) const {
    // The gather's own points of patch j (visibleFractions draws them from the same seed whatever x
    // is), so that the variation about the mean sums the same points' values and its noise cancels.
    const PatchPolygon polygon = mesh_.polygon(j);
    stratifiedPolygonSamples(polygon, options_.gatherRaysPerSide, gatherSeed(j), points);
    atSamples.resize(points.size());
    Rgb sum(0.0);
    double area = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        atSamples[i] = directAt(points[i].point, polygon.normal, mixBits(gatherSeed(j) ^ 0x9e3779b9ull ^ (i << 40)), scratch);
        sum += points[i].area * atSamples[i];
        area += points[i].area;
    }
    return area > 0 ? sum / area : Rgb(0.0);
}

IrradianceRgb Probe::irradiance(const SurfacePoint& at, const glm::dvec3& n, std::span<const Rgb> radiosity) const {
    RADIANT_CHECK_EQ(radiosity.size(), mesh_.patches.size());  // a solution of this mesh
    const glm::dvec3 up = unitNormal(n);
    std::vector<PolygonSample> samples, fineSamples;
    Rgb sum(0.0);
    // gatherDirect's state for this reading: each patch's mean direct irradiance where needed (the
    // near patches and their neighbours), and the radiosities with rho times it taken out (their
    // indirect part, whose slope the neighbours give).
    const bool direct = options_.gatherDirect && rays_ != nullptr && options_.gatherRaysPerSide > 0 &&
                        (!emitters_.empty() || !lighting_.empty());
    std::vector<Rgb> indirect;
    std::vector<Rgb> meanDirect;
    std::vector<std::vector<Rgb>> directAtSamples;  // empty: patch not prepared yet
    std::vector<std::vector<double>> nearWeights;   // the near patches' sample weights, from the first pass
    std::vector<PolygonSample> points, scratch;
    const auto reflectance = [&](std::size_t j) -> const Rgb& {
        return scene_.materials[scene_.surfaces[mesh_.patches[j].surface].material].reflectance;
    };
    const auto prepare = [&](std::size_t j) {
        if (indirect.empty()) {
            indirect.assign(radiosity.begin(), radiosity.end());
            meanDirect.assign(radiosity.size(), Rgb(0.0));
            directAtSamples.assign(radiosity.size(), {});
        }
        if (!directAtSamples[j].empty()) return;
        meanDirect[j] = directOverSamples(j, directAtSamples[j], points, scratch);
        indirect[j] = radiosity[j] - reflectance(j) * meanDirect[j];
    };
    // The patches x may see, with their unoccluded form factor and their visible shares from the
    // gather's coarse rays: a first pass, so that a patch whose neighbours disagree with it can be
    // sampled again below.
    std::vector<double> formFactors(mesh_.patches.size(), 0.0);
    std::vector<VisibleFractions> coarse(rays_ != nullptr && options_.gatherRaysPerSide > 0 ? mesh_.patches.size() : 0);
    for (std::size_t j = 0; j < mesh_.patches.size(); ++j) {
        const Patch& patch = mesh_.patches[j];
        // The patches of x's own planar face contribute nothing (they lie in x's tangent plane).
        if (patch.surface == at.surface && patch.face == at.face) continue;
        const Rgb& b = radiosity[j];
        if (b.x == 0 && b.y == 0 && b.z == 0) continue;
        const PatchPolygon polygon = mesh_.polygon(j);
        // Nor does a patch whose plane holds x (a double-sided face's twin under x): x sees it edge-on.
        if (!inFrontOfPlane(polygon, at.point)) continue;
        formFactors[j] = pointToPolygonFormFactor(at.point, up, polygon.corners());
        if (!(formFactors[j] > 0) || coarse.empty()) continue;
        // A patch near x (its kernel varies across it) is read with its direct light at each of these
        // points, weighed by their share here.
        const glm::dvec3 toPatch = patch.centroid - at.point;
        const bool near = direct && glm::dot(toPatch, toPatch) < kDirectNearDistanceSquaredOverArea * patch.area;
        if (near && nearWeights.empty()) nearWeights.assign(mesh_.patches.size(), {});
        coarse[j] = visibleFractions(at.point, up, polygon, *rays_, options_.gatherRaysPerSide, gatherSeed(j), samples,
                                     near ? &nearWeights[j] : nullptr);
    }
    for (std::size_t j = 0; j < mesh_.patches.size(); ++j) {
        const double f = formFactors[j];
        if (f <= 0) continue;
        const Rgb& b = radiosity[j];
        if (coarse.empty()) {
            sum += b * f;
            continue;
        }
        const PatchPolygon polygon = mesh_.polygon(j);
        const std::span<const std::uint32_t> around =
            std::span<const std::uint32_t>(neighbours_).subspan(neighbourFirst_[j], neighbourFirst_[j + 1] - neighbourFirst_[j]);
        const bool near = !nearWeights.empty() && !nearWeights[j].empty();
        VisibleFractions visible = coarse[j];
        // A patch x sees only in part (a shadow's edge crosses it as seen from x: the lamp behind a
        // block's top edge) is sampled again more finely: 4 x 4 rays read such a patch's visible share
        // 6-11% off, and where it is the lamp that was a floor point's whole error (session 21: -2.0 /
        // -3.2 / -4.1% before a block's shadowed side, +0.15% with 16 x 16; spread over 20 seeds 2.3-4.5%
        // against 0.17-0.33%). So is one whose share differs much from a neighbour's: an edge may cross
        // it as a sliver all its coarse rays miss. The coarse points still carry the direct light's
        // variation below.
        bool partial = visible.formFactor > 0 && visible.formFactor < 1;
        for (const std::uint32_t k : around)
            partial = partial || (formFactors[k] > 0 && std::abs(coarse[k].formFactor - visible.formFactor) > kNeighbourShareGap);
        if (options_.partialRaysPerSide > options_.gatherRaysPerSide && partial)
            visible = visibleFractions(at.point, up, polygon, *rays_, options_.partialRaysPerSide, mixBits(gatherSeed(j) ^ 0x5eedull),
                                       fineSamples);
        Rgb weighed = b * visible.formFactor;
        if (near) {
            // The direct light across a near patch is read point by point; the rest of its radiosity (the
            // indirect part) with the slope of its neighbours' indirect parts, which a penumbra's edge
            // in a neighbour does not tilt.
            prepare(j);
            for (const std::uint32_t k : around) prepare(k);
            Rgb variation(0.0);
            for (std::size_t i = 0; i < nearWeights[j].size(); ++i)
                if (nearWeights[j][i] > 0) variation += nearWeights[j][i] * (directAtSamples[j][i] - meanDirect[j]);
            weighed += reflectance(j) * variation;
            if (options_.gatherSlopes) {
                const std::array<glm::dvec3, 3> g = radiositySlope(mesh_, indirect, j, around);
                for (int c = 0; c < 3; ++c) weighed[c] += glm::dot(g[c], visible.formFactorMoment);
            }
            sum += weighed * f;
            continue;
        }
        // A patch's radiosity is its mean; across it the radiosity may fall steeply (a shadow's edge, the
        // foot of a block), and a point near the patch weighs its near side far more than its far side.
        // Taken as a constant, a floor patch spanning the penumbra before a block's shadowed face was
        // read 6-15% over its kernel-weighted true radiosity from 5 cm up that face (session 20, scratch
        // decomposition against the tracer; ARCHITECTURE "Near contact lines"). A slope from the
        // neighbours, weighed by the kernel's first moment over the visible samples, reads that side.
        if (options_.gatherSlopes) {
            const std::array<glm::dvec3, 3> g = radiositySlope(mesh_, radiosity, j, around);
            for (int c = 0; c < 3; ++c) weighed[c] += glm::dot(g[c], visible.formFactorMoment);
        }
        sum += weighed * f;
    }
    return IrradianceRgb(sum) + lighting_.at(at.point, up);
}

TargetReading Probe::target(const SurfacePoint& at, const glm::dvec3& n, std::size_t surface) const {
    if (surface >= scene_.surfaces.size() || surface + 1 >= mesh_.surfaceFirstPatch.size())
        throw RadiantError({scene_.name, "probe target"}, "no surface number " + std::to_string(surface));
    const glm::dvec3 up = unitNormal(n);
    TargetReading reading;
    reading.surface = surface;
    reading.name = scene_.surfaces[surface].name;
    std::vector<PolygonSample> samples;
    std::vector<glm::dvec3> reversed;
    double solidAngle = 0, formFactor = 0, projected = 0;
    for (std::size_t j = mesh_.surfaceFirstPatch[surface]; j < mesh_.surfaceFirstPatch[surface + 1]; ++j) {
        const PatchPolygon polygon = mesh_.polygon(j);
        const double omega = solidAngleAboveHorizon(at.point, up, polygon.corners()).value();
        // Light leaves only a patch's front, so F counts front faces; the projected solid angle is
        // geometry, integral |cos theta_x| d omega, and counts a patch seen from behind as well.
        const bool frontFacing = glm::dot(polygon.normal, at.point - polygon.centroid) > 0;
        const double f = pointToPolygonFormFactor(at.point, up, polygon.corners());
        double pi_f = std::numbers::pi * f;
        if (!frontFacing) {
            reversed.assign(polygon.corners().rbegin(), polygon.corners().rend());
            pi_f = std::numbers::pi * pointToPolygonFormFactor(at.point, up, reversed);
        }
        // Unoccluded: the front faces alone tile a closed target's silhouette once (its back faces
        // would tile it again).
        if (frontFacing) {
            reading.unoccludedSolidAngle += SolidAngle(omega);
            reading.unoccludedFormFactor += f;
        }
        if (omega <= 0 && pi_f <= 0) continue;
        VisibleFractions visible;
        if (rays_ != nullptr && options_.targetRaysPerSide > 0)
            visible = visibleFractions(at.point, up, polygon, *rays_, options_.targetRaysPerSide,
                                       mixBits(options_.seed ^ mixBits(j)), samples);
        solidAngle += omega * visible.solidAngle;
        formFactor += f * visible.formFactor;
        projected += pi_f * visible.projected;
    }
    reading.solidAngle = SolidAngle(solidAngle);
    reading.formFactor = formFactor;
    reading.projectedSolidAngle = SolidAngle(projected);
    return reading;
}

} // namespace radiant
