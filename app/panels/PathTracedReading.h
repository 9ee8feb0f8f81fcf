#pragma once
// The Probe panel's independent reference: the rendering equation path-traced at the picked point
// (radiometry/reference/) on one background thread at the solver's low priority, refined batch by
// batch until its standard error is small, each refinement published for the panel to show beside
// the solver's value. The panel reads copies; the worker owns the run.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <glm/vec3.hpp>

#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/Scene.h"

namespace radiant {
class RayCaster;
}

namespace radiant::app {

class PathTracedReading {
public:
    PathTracedReading() = default;
    ~PathTracedReading() { stop(); }
    PathTracedReading(const PathTracedReading&) = delete;
    PathTracedReading& operator=(const PathTracedReading&) = delete;

    /// Starts over at (point, normal) on `scene`, whose geometry `rays` was built from; any previous
    /// run stops first. Both are kept alive by the worker.
    void start(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayCaster> rays, const glm::dvec3& point,
               const glm::dvec3& normal);
    /// Stops the worker and forgets the estimate.
    void stop();

    struct State {
        std::optional<ReferenceEstimate> estimate;  ///< the newest refinement
        std::string error;                          ///< why there is none (e.g. a back face)
        bool refining = false;                      ///< the worker is still adding paths
    };
    [[nodiscard]] State state() const;
    /// The scene the running estimate uses (its materials), or null.
    [[nodiscard]] const Scene* scene() const { return scene_.get(); }

    /// Refinement stops when the standard error of E is below this fraction in every band (the
    /// panel's differences show tenths of a percent), after at least kMinimumSamples paths.
    static constexpr double kTargetRelativeError = 1e-3;
    static constexpr std::uint64_t kMinimumSamples = 4096;
    /// The stopping rule: the estimate is as precise as the target asks.
    [[nodiscard]] static bool converged(const ReferenceEstimate& estimate);

private:
    struct Shared {
        mutable std::mutex mutex;
        State state;
    };
    std::shared_ptr<Shared> shared_;
    std::shared_ptr<const Scene> scene_;
    std::jthread worker_;  ///< last: stopped and joined first
};

} // namespace radiant::app
