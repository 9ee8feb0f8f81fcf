#pragma once
// A persistent set of helper threads for parallelFor: a progressive shot is a few milliseconds of
// work, so starting and joining threads on every shot would be a visible share of it. Between jobs a
// helper first waits a short while (kSpin) for the next one, yielding, then sleeps on a condition
// variable: the Cornell box's hierarchical solve runs 133 parallel loops, most of them short, and a
// sleeping helper takes a few microseconds to wake (3 us median, 21 us at the 99th percentile in this
// VM), much longer when its core is busy with something else. A helper that has not joined a job by
// the time the caller has finished it is not waited for (the loops hand out their chunks from an
// atomic counter, so the caller ran them all). Measured on the Cornell box's solve, three rounds
// alternating: 0.097-0.107 s against 0.101-0.117 s, and beside another process keeping one core busy
// 0.171-0.174 s against 0.180-0.203 s.
// One caller uses the pool at a time; a second caller (another solver on another thread) or a nested
// call is told so and runs its loop on its own thread.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace radiant {

class WorkerPool {
public:
    explicit WorkerPool(unsigned helpers) {
        threads_.reserve(helpers);
        for (unsigned t = 0; t < helpers; ++t) threads_.emplace_back([this] { serve(); });
    }
    ~WorkerPool() {
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        threads_.clear();  // joins
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    [[nodiscard]] unsigned helperCount() const { return static_cast<unsigned>(threads_.size()); }

    /// Runs job() on the calling thread and on every helper that joins in time, and returns when all
    /// of those have returned. job must not throw, and must be done whoever runs it (a helper that
    /// joins late may find nothing left). Returns false, running nothing, when the pool is in use by
    /// another caller or when called from inside a job.
    bool tryRunOnAll(const std::function<void()>& job) {
        if (insideJob() || !inUse_.try_lock()) return false;
        const std::lock_guard release(inUse_, std::adopt_lock);
        bool sleepers = false;
        {
            const std::lock_guard lock(mutex_);
            job_ = &job;
            open_ = true;
            ++generation_;
            published_.store(generation_, std::memory_order_release);
            sleepers = sleeping_ > 0;
        }
        if (sleepers) wake_.notify_all();
        insideJob() = true;
        job();
        insideJob() = false;
        std::unique_lock lock(mutex_);
        open_ = false;  // from here a helper that wakes skips this job
        finished_.wait(lock, [this] { return running_ == 0; });
        job_ = nullptr;
        return true;
    }

    /// The process-wide pool: one helper per hardware thread beyond the caller's.
    static WorkerPool& shared() {
        static WorkerPool pool(std::max(1u, std::thread::hardware_concurrency()) - 1);
        return pool;
    }

    /// True on a thread that is running a job of any pool (nested parallel loops stay serial).
    static bool calledFromJob() { return insideJob(); }

private:
    static bool& insideJob() {
        thread_local bool inside = false;
        return inside;
    }

    /// How long a helper waits for the next job before it sleeps.
    static constexpr std::chrono::microseconds kSpin{300};

    /// Waits up to kSpin for a job after `seen`, without sleeping, yielding the core to any other
    /// thread that wants it (spinning with pause alone made a solve 6% slower beside another busy
    /// process: the spinning helper took turns from the solver's own threads).
    void spinFor(std::uint64_t seen) const {
        const auto until = std::chrono::steady_clock::now() + kSpin;
        while (published_.load(std::memory_order_acquire) == seen) {
            if (std::chrono::steady_clock::now() >= until) return;
            std::this_thread::yield();
        }
    }

    void serve() {
        insideJob() = true;
        std::uint64_t seen = 0;
        for (;;) {
            spinFor(seen);
            std::unique_lock lock(mutex_);
            ++sleeping_;
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            --sleeping_;
            if (stopping_) return;
            seen = generation_;
            if (!open_) continue;  // the caller finished this job alone
            ++running_;
            const std::function<void()>* job = job_;
            lock.unlock();
            (*job)();
            lock.lock();
            if (--running_ == 0) finished_.notify_one();
        }
    }

    std::mutex inUse_;  ///< held by the caller of tryRunOnAll for the whole job
    std::mutex mutex_;  ///< guards the fields below but published_
    std::condition_variable wake_, finished_;
    const std::function<void()>* job_ = nullptr;
    std::uint64_t generation_ = 0;
    std::atomic<std::uint64_t> published_{0};  ///< generation_, for the spinning helpers
    unsigned running_ = 0;   ///< helpers inside the current job
    unsigned sleeping_ = 0;  ///< helpers waiting on wake_
    bool open_ = false;      ///< the current job still takes helpers
    bool stopping_ = false;
    std::vector<std::jthread> threads_;  ///< last: joined before the fields above go away
};

} // namespace radiant
