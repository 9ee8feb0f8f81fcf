#include "app/panels/PathTracedReading.h"

#include <cstdint>
#include <exception>
#include <thread>
#include <utility>

#include "app/solver/ThreadPriority.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/reference/PathTracer.h"
#include "radiometry/reference/ReferencePoint.h"

namespace radiant::app {

void PathTracedReading::start(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayCaster> rays,
                              const glm::dvec3& point, const glm::dvec3& normal) {
    stop();
    scene_ = scene;
    shared_ = std::make_shared<Shared>();
    shared_->state.refining = true;
    worker_ = std::jthread([shared = shared_, scene = std::move(scene), rays = std::move(rays), point,
                            normal](std::stop_token stopToken) {
        yieldToTheDisplay();  // the helper threads of each batch inherit the low priority
        const auto publish = [&](auto&& change) {
            const std::lock_guard lock(shared->mutex);
            change(shared->state);
        };
        try {
            const ReferencePoint at = locateReferencePoint(*scene, point, normal);
            const PathTracer tracer(*scene, *rays);
            ReferenceRunOptions options;
            // A batch is 512 paths, a few milliseconds: a new pick (which joins this worker on the
            // window's thread) never waits long.
            options.samplesPerBatch = 512;
            // One thread, this one: the reference never holds more than one core, so llvmpipe's
            // rasterisers (one per core) always find a core it does not contend for. With one per
            // core it cost the probe rows of `radiant bench --only frames` about a quarter of their
            // frame time while it refined (README, "Benchmarks").
            options.threads = 1;
            ReferenceRun run(tracer, at, options);
            for (std::uint64_t samples = 0;;) {
                if (samples >= kMinimumSamples && !shared->waitForStillView(stopToken)) break;
                run.addBatches(1);
                const ReferenceEstimate estimate = run.estimate();
                samples = estimate.samples;
                const bool done = converged(estimate);
                publish([&](State& state) {
                    state.estimate = estimate;
                    state.refining = !done;
                });
                if (done || stopToken.stop_requested()) break;
            }
        } catch (const RadiantError& e) {
            // Its element names the command line's --point or --normal; the detail already says
            // "the point (...)" or "the normal (...)", which is what the lab's probe is.
            publish([&](State& state) {
                state.error = e.where().file.empty() ? e.detail() : e.where().file + ": " + e.detail();
                state.refining = false;
            });
        } catch (const std::exception& e) {
            publish([&](State& state) {
                state.error = e.what();
                state.refining = false;
            });
        }
    });
}

bool PathTracedReading::Shared::waitForStillView(const std::stop_token& stopToken) {
    using Clock = std::chrono::steady_clock;
    bool said = false;
    for (;;) {
        if (stopToken.stop_requested()) return false;
        const Clock::time_point frame{Clock::duration{lastFrame.load(std::memory_order_relaxed)}};
        const Clock::duration sinceFrame = Clock::now() - frame;
        if (sinceFrame >= kStillViewFor) break;
        if (!said) {
            const std::lock_guard lock(mutex);
            state.waitingForStillView = said = true;
        }
        std::this_thread::sleep_for(kStillViewFor - sinceFrame);
    }
    if (said) {
        const std::lock_guard lock(mutex);
        state.waitingForStillView = false;
    }
    return true;
}

void PathTracedReading::noteFrameDrawn() {
    if (shared_) shared_->lastFrame.store(std::chrono::steady_clock::now().time_since_epoch().count(), std::memory_order_relaxed);
}

void PathTracedReading::stop() {
    if (worker_.joinable()) {
        worker_.request_stop();
        worker_.join();
    }
    shared_.reset();
    scene_.reset();
}

bool PathTracedReading::converged(const ReferenceEstimate& estimate) {
    return estimate.samples >= kMinimumSamples && estimate.relativeStandardError() <= kTargetRelativeError;
}

PathTracedReading::State PathTracedReading::state() const {
    if (!shared_) return {};
    const std::lock_guard lock(shared_->mutex);
    return shared_->state;
}

} // namespace radiant::app
