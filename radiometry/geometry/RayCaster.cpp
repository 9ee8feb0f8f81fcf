// Ray casting through Embree 3's BVH (Wald et al., "Embree: a kernel framework for efficient CPU
// ray tracing", ACM TOG 2014). Faces are fan-triangulated into one triangle geometry; each triangle
// remembers its (surface, face) and its face's plane in double precision.
//
// Embree works in float. Two guards keep a ray from reporting the surface it starts (or ends) on:
// an intersection filter rejects triangles whose plane contains the ray's origin (or, for
// segments, its end point) - tested in double against the face's own plane, to the precision of
// positions stored as float (a glTF file's, 6e-8 of their size: a face's corners are that far off
// one plane) - and segments are shortened at both ends by no more than that precision. A longer
// cut (1e-5 of the length, once) let a segment leaving a face a hair from its edge skip the
// neighbour it crosses there: 1 in 10^4 such rays left a closed sphere through its wall. The same filter makes a
// two-sided face (two surfaces back to back, FaceSide) answer a ray with the side it meets from
// the front: the twin's plane holds the origin of any ray leaving the other side, so it never
// blocks it at distance 0, and a ray arriving from behind is handed to the twin facing it.
#include "radiometry/geometry/RayCaster.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"

namespace radiant {
namespace {

struct TriangleInfo {
    glm::dvec3 normal;    ///< unit, the face's front
    double planeOffset;   ///< normal . p for every p on the face
    std::uint32_t surface;
    std::uint32_t face;
    bool twoSided;        ///< a coincident reversed twin exists (Surface::side is Front or Back)
};

// Segments are shortened at each end by the plane tolerance, but never by more than this fraction
// of their length.
constexpr double kRelativeSegmentEpsilon = 1e-5;
// Points within this many scene sizes (extent plus distance from the origin, the size float
// positions round to) of a face's plane lie on it: float's 6e-8, with a margin.
constexpr double kPlaneTolerance = 1e-7;

std::atomic<std::uint64_t> constructions{0};

struct TriangleTable {
    std::vector<TriangleInfo> triangles;  ///< by Embree primID
    glm::dvec3 origin{0.0};    ///< float coordinates are relative to the scene's centre, for precision
    double extent = 1;         ///< bounding box diagonal, m
    double planeTolerance = 0; ///< m
};

} // namespace

struct RayCaster::Impl : TriangleTable {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    /// The faces that can block a segment between points of the scene's faces (see
    /// occludersBetweenFaces), with their own triangle table: the packets' scene. Null when every face
    /// may block (or the test was too costly): the packets then trace `scene`.
    RTCScene occluderScene = nullptr;
    TriangleTable occluders;
    /// Per face (surfaces in order, faces in order): occludersBetweenFaces, empty when every face may block.
    std::vector<bool> faceMayBlock;

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        if (occluderScene) rtcReleaseScene(occluderScene);
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

/// RTCIntersectContext extended with the query's end points (Embree 3's documented way to pass
/// per-query data to filter functions: the context is the first member).
struct QueryContext {
    RTCIntersectContext embree;
    const TriangleTable* impl;
    glm::dvec3 start;
    glm::dvec3 end;
    bool hasEnd;
    glm::dvec3 direction;  ///< of an intersect query; zero for occlusion, where either twin blocks
    bool frontOnly;        ///< pass through every face met from behind (picking what the view shows)
    /// A packet of segments (occludedPacket): each ray's end points by its id; null for one ray.
    const glm::dvec3* starts = nullptr;
    const glm::dvec3* ends = nullptr;
};

void rejectHitsOnEndPointPlanes(const RTCFilterFunctionNArguments* args) {
    const auto* query = reinterpret_cast<const QueryContext*>(args->context);
    const double tolerance = query->impl->planeTolerance;
    for (unsigned lane = 0; lane < args->N; ++lane) {
        if (args->valid[lane] == 0) continue;
        const TriangleInfo& triangle = query->impl->triangles[RTCHitN_primID(args->hit, args->N, lane)];
        const auto onPlane = [&](const glm::dvec3& p) {
            return std::abs(glm::dot(triangle.normal, p) - triangle.planeOffset) <= tolerance;
        };
        // A packet's lanes may reach the filter in any order: each ray's id names its segment.
        const unsigned id = query->starts ? RTCRayN_id(args->ray, args->N, lane) : 0;
        const glm::dvec3& start = query->starts ? query->starts[id] : query->start;
        const glm::dvec3& end = query->starts ? query->ends[id] : query->end;
        if (onPlane(start) || (query->hasEnd && onPlane(end)) ||
            ((triangle.twoSided || query->frontOnly) && glm::dot(triangle.normal, query->direction) > 0))
            args->valid[lane] = 0;
    }
}

void throwOnDeviceError(RTCDevice device, const std::string& what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw RadiantError({"Embree", what}, "Embree error code " + std::to_string(static_cast<int>(error)));
}

QueryContext makeContext(const TriangleTable& impl, const glm::dvec3& start, const glm::dvec3& end, bool hasEnd,
                         const glm::dvec3& direction = glm::dvec3(0.0), bool frontOnly = false) {
    QueryContext context{};
    context.direction = direction;
    context.frontOnly = frontOnly;
    rtcInitIntersectContext(&context.embree);
    context.impl = &impl;
    context.start = start;
    context.end = end;
    context.hasEnd = hasEnd;
    return context;
}

void setRay(RTCRay& ray, const glm::dvec3& localOrigin, const glm::dvec3& unitDirection, double tnear, double tfar) {
    ray.org_x = static_cast<float>(localOrigin.x);
    ray.org_y = static_cast<float>(localOrigin.y);
    ray.org_z = static_cast<float>(localOrigin.z);
    ray.dir_x = static_cast<float>(unitDirection.x);
    ray.dir_y = static_cast<float>(unitDirection.y);
    ray.dir_z = static_cast<float>(unitDirection.z);
    ray.tnear = static_cast<float>(tnear);
    ray.tfar = static_cast<float>(std::min(tfar, static_cast<double>(std::numeric_limits<float>::max())));
    ray.time = 0;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
}

/// An Embree scene of the faces keep(surface, face) accepts, fan-triangulated, each triangle's plane
/// and owner in `table` (its origin set), with the end-point filter.
template <class Keep>
RTCScene buildScene(RTCDevice device, const Scene& scene, TriangleTable& table, Keep&& keep) {
    RTCScene built = rtcNewScene(device);
    rtcSetSceneFlags(built, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(built, RTC_BUILD_QUALITY_HIGH);
    std::size_t vertexCount = 0, triangleCount = 0;
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s)
        for (std::uint32_t f = 0; f < scene.surfaces[s].faces.size(); ++f) {
            const Face& face = scene.surfaces[s].faces[f];
            if (face.vertices.size() < 3 || !keep(s, f)) continue;
            vertexCount += face.vertices.size();
            triangleCount += face.vertices.size() - 2;
        }
    if (triangleCount > 0) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
        auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangleCount));
        if (!vertices || !indices) {
            rtcReleaseGeometry(geometry);
            throwOnDeviceError(device, "geometry buffers");
        }
        table.triangles.reserve(triangleCount);
        std::uint32_t nextVertex = 0;
        std::size_t nextIndex = 0;
        for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
            const Surface& surface = scene.surfaces[s];
            for (std::uint32_t f = 0; f < surface.faces.size(); ++f) {
                const Face& face = surface.faces[f];
                if (face.vertices.size() < 3 || !keep(s, f)) continue;
                const std::uint32_t first = nextVertex;
                for (const glm::dvec3& v : face.vertices) {
                    const glm::dvec3 local = v - table.origin;
                    vertices[3 * nextVertex + 0] = static_cast<float>(local.x);
                    vertices[3 * nextVertex + 1] = static_cast<float>(local.y);
                    vertices[3 * nextVertex + 2] = static_cast<float>(local.z);
                    ++nextVertex;
                }
                const TriangleInfo info{face.normal, glm::dot(face.normal, face.vertices[0]), s, f,
                                        surface.side != FaceSide::Single};
                // Fan from the first corner: faces are convex.
                for (std::uint32_t k = 1; k + 1 < face.vertices.size(); ++k) {
                    indices[nextIndex++] = first;
                    indices[nextIndex++] = first + k;
                    indices[nextIndex++] = first + k + 1;
                    table.triangles.push_back(info);
                }
            }
        }
        rtcSetGeometryIntersectFilterFunction(geometry, rejectHitsOnEndPointPlanes);
        rtcSetGeometryOccludedFilterFunction(geometry, rejectHitsOnEndPointPlanes);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(built, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(built);
    return built;
}

/// Above this many face-vertex pairs the hull test is not run: every face stays an occluder.
constexpr double kMaxHullTests = 4e6;

/// Per face (surfaces in order, faces in order): whether it can block a segment between two points
/// of the scene's faces. A face whose plane has every vertex of the scene on or in front of it
/// (within `tolerance` m) bounds the scene: such a segment cannot cross it and meets it only at an
/// end on its plane, which the filter ignores anyway. Empty when the test would cost too much.
std::vector<bool> occludersBetweenFaces(const Scene& scene, double tolerance) {
    std::size_t faces = 0, vertices = 0;
    for (const Surface& surface : scene.surfaces) {
        faces += surface.faces.size();
        for (const Face& face : surface.faces) vertices += face.vertices.size();
    }
    if (static_cast<double>(faces) * static_cast<double>(vertices) > kMaxHullTests) return {};
    std::vector<bool> blocks;
    blocks.reserve(faces);
    for (const Surface& surface : scene.surfaces)
        for (const Face& face : surface.faces) {
            bool bounds = !face.vertices.empty();
            for (const Surface& other : scene.surfaces)
                for (const Face& g : other.faces)
                    for (const glm::dvec3& v : g.vertices)
                        bounds = bounds && glm::dot(face.normal, v - face.vertices[0]) >= -tolerance;
            blocks.push_back(!bounds);
        }
    return blocks;
}

} // namespace

RayCaster::RayCaster(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    constructions.fetch_add(1, std::memory_order_relaxed);
    Impl& impl = *impl_;
    impl.device = rtcNewDevice(nullptr);
    if (!impl.device)
        throw RadiantError({scene.name, "ray caster"}, "cannot create an Embree device (error code " +
                                                           std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");

    glm::dvec3 lower(std::numeric_limits<double>::max());
    glm::dvec3 upper(std::numeric_limits<double>::lowest());
    std::size_t vertexCount = 0;
    for (const Surface& surface : scene.surfaces)
        for (const Face& face : surface.faces) {
            if (face.vertices.size() < 3) continue;
            vertexCount += face.vertices.size();
            for (const glm::dvec3& v : face.vertices) {
                lower = glm::min(lower, v);
                upper = glm::max(upper, v);
            }
        }
    if (vertexCount > 0) {
        impl.origin = 0.5 * (lower + upper);
        impl.extent = std::max(glm::length(upper - lower), 1e-30);
    }
    impl.planeTolerance = kPlaneTolerance * (impl.extent + glm::length(impl.origin));

    impl.scene = buildScene(impl.device, scene, impl, [](std::uint32_t, std::uint32_t) { return true; });
    throwOnDeviceError(impl.device, scene.name.empty() ? "building the BVH" : scene.name);
    // Faces on the scene's hull facing in (a room's walls, floor and ceiling) never block a segment
    // between two points of its faces: the packets, which only ever trace such segments
    // (hierarchical radiosity's visibility sets), traverse the other faces alone.
    const std::vector<bool> blocks = occludersBetweenFaces(scene, impl.planeTolerance);
    if (!blocks.empty() && std::find(blocks.begin(), blocks.end(), false) != blocks.end()) {
        impl.faceMayBlock = blocks;
        impl.occluders = TriangleTable{{}, impl.origin, impl.extent, impl.planeTolerance};
        std::vector<std::size_t> firstFace;  // flat index of each surface's first face
        std::size_t flat = 0;
        for (const Surface& surface : scene.surfaces) {
            firstFace.push_back(flat);
            flat += surface.faces.size();
        }
        impl.occluderScene = buildScene(impl.device, scene, impl.occluders,
                                        [&](std::uint32_t s, std::uint32_t f) { return blocks[firstFace[s] + f]; });
        throwOnDeviceError(impl.device, scene.name.empty() ? "building the occluders' BVH" : scene.name);
    }
}

bool RayCaster::mayBlock(std::size_t face) const {
    return face >= impl_->faceMayBlock.size() || impl_->faceMayBlock[face];
}

RayCaster::~RayCaster() = default;
std::uint64_t RayCaster::constructed() { return constructions.load(std::memory_order_relaxed); }
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

std::optional<RayHit> RayCaster::intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                           double maxDistance) const {
    return nearestHit(origin, direction, maxDistance, false);
}

std::optional<RayHit> RayCaster::intersectFront(const glm::dvec3& origin, const glm::dvec3& direction,
                                                double maxDistance) const {
    return nearestHit(origin, direction, maxDistance, true);
}

std::optional<RayHit> RayCaster::nearestHit(const glm::dvec3& origin, const glm::dvec3& direction, double maxDistance,
                                            bool frontOnly) const {
    const double length = glm::length(direction);
    if (!(length > 0) || !(maxDistance > 0)) return std::nullopt;
    const glm::dvec3 unit = direction / length;
    QueryContext context = makeContext(*impl_, origin, origin, false, unit, frontOnly);
    RTCRayHit rayHit{};
    setRay(rayHit.ray, origin - impl_->origin, unit, 0.0, maxDistance);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context.embree, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    const TriangleInfo& triangle = impl_->triangles[rayHit.hit.primID];
    RayHit hit;
    hit.normal = triangle.normal;
    hit.surface = triangle.surface;
    hit.face = triangle.face;
    // Refine the float distance against the face's plane in double.
    const double denominator = glm::dot(triangle.normal, unit);
    double distance = static_cast<double>(rayHit.ray.tfar);
    if (std::abs(denominator) > 1e-6) {
        const double exact = (triangle.planeOffset - glm::dot(triangle.normal, origin)) / denominator;
        if (exact > 0 && std::abs(exact - distance) <= 1e-4 * impl_->extent + 1e-4 * distance) distance = exact;
    }
    hit.distance = distance;
    hit.point = origin + unit * distance;
    return hit;
}

namespace {

/// One segment through rtcOccluded1 (RayCaster::occluded; also a span of one segment, for which a
/// packet's set-up and 4-wide traversal cost more than the ray: the hierarchical rows' faint terms).
bool occludedSingle(RTCScene scene, const TriangleTable& table, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 segment = b - a;
    const double length = glm::length(segment);
    if (!(length > 0)) return false;
    const double epsilon = std::min(table.planeTolerance, kRelativeSegmentEpsilon * length);
    QueryContext context = makeContext(table, a, b, true);
    RTCRay ray{};
    setRay(ray, a - table.origin, segment / length, epsilon, length - epsilon);
    rtcOccluded1(scene, &context.embree, &ray);
    return ray.tfar < 0;  // Embree marks an occluded ray by setting tfar to -infinity
}

} // namespace

bool RayCaster::occluded(const glm::dvec3& a, const glm::dvec3& b) const { return occludedSingle(impl_->scene, *impl_, a, b); }

namespace {

/// One packet of up to W segments through rtcOccluded4 or rtcOccluded8 (see RayCaster::occluded).
template <class Packet, std::size_t W>
void occludedPacket(RTCScene scene, const TriangleTable& table, std::span<const glm::dvec3> a, std::span<const glm::dvec3> b,
                    std::span<bool> blocked) {
    QueryContext context = makeContext(table, a[0], b[0], true);
    context.starts = a.data();
    context.ends = b.data();
    alignas(32) Packet rays{};
    alignas(32) std::array<int, W> valid{};
    for (std::size_t i = 0; i < a.size(); ++i) {
        const glm::dvec3 segment = b[i] - a[i];
        const double length = glm::length(segment);
        if (!(length > 0)) continue;  // an empty segment meets nothing
        const double epsilon = std::min(table.planeTolerance, kRelativeSegmentEpsilon * length);
        const glm::dvec3 origin = a[i] - table.origin, direction = segment * (1.0 / length);
        rays.org_x[i] = static_cast<float>(origin.x);
        rays.org_y[i] = static_cast<float>(origin.y);
        rays.org_z[i] = static_cast<float>(origin.z);
        rays.dir_x[i] = static_cast<float>(direction.x);
        rays.dir_y[i] = static_cast<float>(direction.y);
        rays.dir_z[i] = static_cast<float>(direction.z);
        rays.tnear[i] = static_cast<float>(epsilon);
        rays.tfar[i] = static_cast<float>(std::min(length - epsilon, static_cast<double>(std::numeric_limits<float>::max())));
        rays.mask[i] = 0xFFFFFFFFu;
        rays.id[i] = static_cast<unsigned>(i);
        valid[i] = -1;
    }
    if constexpr (W == 4)
        rtcOccluded4(valid.data(), scene, &context.embree, &rays);
    else
        rtcOccluded8(valid.data(), scene, &context.embree, &rays);
    for (std::size_t i = 0; i < a.size(); ++i) blocked[i] = valid[i] != 0 && rays.tfar[i] < 0;
}

} // namespace

void RayCaster::occluded(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b, std::span<bool> blocked) const {
    // Packets through Embree's 4- and 8-wide traversal: the segments of one visibility set run between
    // the same two elements, so they share most of the BVH's nodes, and one call replaces several.
    constexpr std::size_t kWidth = 8;
    for (std::size_t first = 0; first < a.size(); first += kWidth) {
        const std::size_t count = std::min(kWidth, a.size() - first);
        RTCScene scene = impl_->occluderScene ? impl_->occluderScene : impl_->scene;
        const TriangleTable& table = impl_->occluderScene ? impl_->occluders : *impl_;
        if (count == 1)
            blocked[first] = occludedSingle(scene, table, a[first], b[first]);
        else if (count <= 4)
            occludedPacket<RTCRay4, 4>(scene, table, a.subspan(first, count), b.subspan(first, count), blocked.subspan(first, count));
        else
            occludedPacket<RTCRay8, 8>(scene, table, a.subspan(first, count), b.subspan(first, count), blocked.subspan(first, count));
    }
}

} // namespace radiant
