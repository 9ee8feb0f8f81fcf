#pragma once
// The hemicube over the probe point, shared by the Hemisphere and Integrals panels: rendered on the
// GPU when the point, the mesh or the resolution changes (at most once a frame), and gathered into
// form factors and irradiance when asked after the solve moved. Main thread only (it draws with GL).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "app/solver/Snapshot.h"
#include "radiometry/hemicube/HemicubeGather.h"
#include "render/hemicube/HemicubeRenderer.h"

namespace radiant::app {

/// Where the hemicube stands: a picked point on a surface and its front normal.
struct HemicubePoint {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 0, 1};
    std::uint32_t surface = 0;
};

class HemicubeSession {
public:
    using PointSource = std::function<std::optional<HemicubePoint>()>;
    using SnapshotSource = std::function<std::shared_ptr<const Snapshot>()>;
    HemicubeSession(SnapshotSource snapshots, PointSource points);
    ~HemicubeSession();

    /// Re-renders when anything it depends on changed; cheap otherwise.
    void update();

    [[nodiscard]] int resolution() const { return resolution_; }
    void setResolution(int resolution) { resolution_ = resolution; }
    [[nodiscard]] bool ready() const { return capture_.has_value(); }
    [[nodiscard]] const render::HemicubeCapture& capture() const { return *capture_; }
    /// Gathered on first use after the solve moved: with the Hemisphere and Integrals panels closed,
    /// a running solve costs no gather per snapshot (~200k hemicube pixels at 256).
    [[nodiscard]] const HemicubeGatherResult& gathered() const;
    [[nodiscard]] const Snapshot& snapshot() const { return *snapshot_; }
    [[nodiscard]] const std::optional<HemicubePoint>& point() const { return point_; }
    /// Increases whenever capture() or gathered() changed: views re-colour only then.
    [[nodiscard]] std::uint64_t version() const { return version_; }
    /// Increases only when the item buffer was re-rendered (point, mesh or resolution changed).
    [[nodiscard]] std::uint64_t captureVersion() const { return captureVersion_; }
    [[nodiscard]] double lastRenderSeconds() const { return lastRenderSeconds_; }

    /// L = B / pi (W/(m^2 sr), per band) of the patch seen along a direction in the capture's local
    /// frame (capture().frame, z = normal); zero toward open sky or a surface's back.
    [[nodiscard]] Rgb radianceToward(const glm::dvec3& localDirection) const;

private:
    SnapshotSource snapshots_;
    PointSource points_;
    /// With the twisted hemicube the Cornell light's F is within 0.2 % of the exact kernel at 256
    /// (0.4 % at 128) from floor points; a frame-time cost only when the point moves.
    int resolution_ = 256;
    std::shared_ptr<const Snapshot> snapshot_;
    std::optional<HemicubePoint> point_;
    std::unique_ptr<render::HemicubeRenderer> renderer_;
    std::uint64_t rendererMesh_ = 0;
    std::optional<render::HemicubeCapture> capture_;
    mutable HemicubeGatherResult gathered_;
    mutable bool gatherStale_ = true;
    std::uint64_t capturedGeneration_ = 0;
    std::uint64_t version_ = 0;
    std::uint64_t captureVersion_ = 0;
    double lastRenderSeconds_ = 0;
};

} // namespace radiant::app
