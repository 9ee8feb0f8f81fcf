#pragma once
// Ray casting against the scene's faces through Embree's BVH: visibility for form factors and the
// probe, and picking in the window. Built once per scene (the lab shares one per loaded scene through
// its snapshots and solvers, SolverOptions::rays) and thread-safe for concurrent queries: every query
// is const, the Embree scene is committed in the constructor and never changed after, and Embree
// allows any number of threads to trace a committed scene; each query's state lives on its stack.
// It holds geometry only (faces, normals, which surface is two-sided), never materials, so a
// materials edit keeps it valid.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include <glm/vec3.hpp>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct RayHit {
    double distance = 0;       ///< metres along the (unit) direction
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 0, 1};  ///< the face's geometric normal (its front side)
    std::uint32_t surface = 0;
    std::uint32_t face = 0;    ///< within the surface
};

class RayCaster {
public:
    explicit RayCaster(const Scene& scene);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;
    RayCaster(RayCaster&&) noexcept;
    RayCaster& operator=(RayCaster&&) noexcept;

    /// Nearest hit along origin + t * direction for t in (0, maxDistance]. direction need not be unit.
    [[nodiscard]] std::optional<RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                                  double maxDistance = 1e30) const;
    /// As intersect, passing through every face met from behind (its normal along the ray): the
    /// face a click on the 3D view means, which draws each face from its front only.
    [[nodiscard]] std::optional<RayHit> intersectFront(const glm::dvec3& origin, const glm::dvec3& direction,
                                                       double maxDistance = 1e30) const;
    /// True when something blocks the open segment between a and b. The end points lie on surfaces;
    /// the segment is shortened by a relative epsilon at both ends so neither end's own face counts.
    [[nodiscard]] bool occluded(const glm::dvec3& a, const glm::dvec3& b) const;
    /// The same for segments a[i]-b[i] whose ends lie on the scene's faces (or in front of every face
    /// bounding the scene), traced as packets (faster for segments that run close together) through
    /// the faces that can block such a segment: faces whose plane has the whole scene on or in front
    /// of it (a room's walls, floor and ceiling) are left out. blocked[i] tells whether segment i is
    /// blocked. The spans have one size.
    void occluded(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b, std::span<bool> blocked) const;

    /// Whether face `face` (counted over the surfaces in order, then their faces) can block a segment
    /// between two points of the scene's faces: false for a face on the scene's hull facing in (a
    /// room's walls, floor and ceiling), which such a segment meets only at an end. The segments'
    /// span overload leaves those faces out; so may other tests of the same segments.
    [[nodiscard]] bool mayBlock(std::size_t face) const;

    /// Ray casters constructed in this process so far: a BVH build is the cost the lab shares, and
    /// tests count them. Atomic; it only counts, nothing depends on it.
    [[nodiscard]] static std::uint64_t constructed();

private:
    [[nodiscard]] std::optional<RayHit> nearestHit(const glm::dvec3& origin, const glm::dvec3& direction,
                                                   double maxDistance, bool frontOnly) const;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace radiant
