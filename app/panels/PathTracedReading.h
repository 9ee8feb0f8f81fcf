#pragma once
// The Probe panel's independent reference: the rendering equation path-traced at the picked point
// (radiometry/reference/) on one background thread, refined batch by batch until its standard error
// is small, each refinement published for the panel to show beside the solver's value. The panel
// reads copies; the worker owns the run.
//
// It refines while the view is still. Its first kMinimumSamples paths (a few milliseconds) give a
// first estimate at once; after that a batch starts only when no frame has been drawn for
// kStillViewFor, so a running solve or a moving camera, which redraw the view back to back, keep the
// cores for the view's frames. On two cores with software GL the refining tracer put the probe's
// idle frames at 36 ms (99th percentile, `radiant bench --only frames`) against 23 ms without a
// probe, at nice 10 and at SCHED_IDLE alike; the idle lab's wake-ups to show the refinement are far
// enough apart for it to refine between them.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stop_token>
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
    /// Called on the window's thread each frame: refinement waits until frames stop for kStillViewFor.
    void noteFrameDrawn();

    struct State {
        std::optional<ReferenceEstimate> estimate;  ///< the newest refinement
        std::string error;                          ///< why there is none (e.g. a back face)
        bool refining = false;                      ///< the worker is still adding paths
        bool waitingForStillView = false;           ///< refining, but paused while frames are drawn
    };
    [[nodiscard]] State state() const;
    /// The scene the running estimate uses (its materials), or null.
    [[nodiscard]] const Scene* scene() const { return scene_.get(); }

    /// Refinement stops when the standard error of E is below this fraction in every band (the
    /// panel's differences show tenths of a percent), after at least kMinimumSamples paths.
    static constexpr double kTargetRelativeError = 1e-3;
    static constexpr std::uint64_t kMinimumSamples = 4096;
    /// Refinement past the first estimate waits until no frame was drawn for this long (the idle
    /// lab wakes every 0.5 s to show the refinement).
    static constexpr std::chrono::milliseconds kStillViewFor{100};
    /// The stopping rule: the estimate is as precise as the target asks.
    [[nodiscard]] static bool converged(const ReferenceEstimate& estimate);

private:
    struct Shared {
        mutable std::mutex mutex;
        State state;
        /// steady_clock ticks of the last frame drawn (0: none yet)
        std::atomic<std::chrono::steady_clock::rep> lastFrame{0};
        /// On the worker: sleeps while frames are drawn (the last under kStillViewFor ago), saying
        /// so in `state`; false when a stop was requested meanwhile.
        bool waitForStillView(const std::stop_token& stopToken);
    };
    std::shared_ptr<Shared> shared_;
    std::shared_ptr<const Scene> scene_;
    std::jthread worker_;  ///< last: stopped and joined first
};

} // namespace radiant::app
