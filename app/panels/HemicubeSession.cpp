#include "app/panels/HemicubeSession.h"

#include <chrono>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>

#include "radiometry/hemisphere/HemisphericalCoordinates.h"

namespace radiant::app {

HemicubeSession::HemicubeSession(SnapshotSource snapshots, PointSource points)
    : snapshots_(std::move(snapshots)), points_(std::move(points)) {}

HemicubeSession::~HemicubeSession() = default;

void HemicubeSession::update() {
    std::shared_ptr<const Snapshot> newest = snapshots_();
    std::optional<HemicubePoint> point = points_();
    if (!newest || !newest->mesh || !newest->scene || !point) {
        snapshot_ = std::move(newest);
        point_.reset();
        capture_.reset();
        return;
    }
    const bool pointMoved = !point_ || point_->point != point->point || point_->normal != point->normal;
    const bool meshChanged = !renderer_ || rendererMesh_ != newest->meshGeneration;
    const bool resolutionChanged = !capture_ || capture_->layout.resolution() != resolution_;
    const bool solveMoved = capturedGeneration_ != newest->generation;
    snapshot_ = std::move(newest);
    point_ = point;
    if (!(pointMoved || meshChanged || resolutionChanged || solveMoved)) return;

    if (meshChanged) {
        renderer_ = std::make_unique<render::HemicubeRenderer>(*snapshot_->mesh);
        rendererMesh_ = snapshot_->meshGeneration;
    }
    // Geometry decides the picture; a new solve only changes the radiances gathered from it.
    if (pointMoved || meshChanged || resolutionChanged) {
        const auto start = std::chrono::steady_clock::now();
        capture_ = renderer_->capture(point->point, point->normal, resolution_);
        lastRenderSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++captureVersion_;
    }
    gatherStale_ = true;
    capturedGeneration_ = snapshot_->generation;
    ++version_;
}

const HemicubeGatherResult& HemicubeSession::gathered() const {
    if (gatherStale_ && capture_ && snapshot_) {
        const std::span<const Rgb> radiosity = snapshot_->radiosity.size() == snapshot_->mesh->size()
                                                   ? std::span<const Rgb>(snapshot_->radiosity)
                                                   : std::span<const Rgb>();
        gathered_ = gatherHemicube(capture_->layout, capture_->items, *snapshot_->mesh,
                                   snapshot_->scene->surfaces.size(), radiosity);
        gatherStale_ = false;
    }
    return gathered_;
}

Rgb HemicubeSession::radianceToward(const glm::dvec3& localDirection) const {
    if (!capture_ || localDirection.z < 0) return Rgb(0.0);
    const std::uint32_t item = capture_->items[capture_->layout.pixelIndexOf(localDirection)];
    if (!hemicubeItemIsFront(item)) return Rgb(0.0);
    const std::size_t patch = hemicubeItemPatch(item);
    if (patch >= snapshot_->radiosity.size()) return Rgb(0.0);
    return snapshot_->radiosity[patch] / std::numbers::pi;
}

} // namespace radiant::app
