#pragma once
// A persistent set of helper threads for parallelFor: a progressive shot is a few milliseconds of
// work, so starting and joining threads on every shot would be a visible share of it. The helpers
// sleep on a condition variable between jobs. One caller uses the pool at a time; a second caller
// (another solver on another thread) or a nested call is told so and runs its loop on its own thread.
#include <algorithm>
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

    /// Runs job() on the calling thread and on every helper at once and returns when all have
    /// returned. job must not throw. Returns false, running nothing, when the pool is in use by
    /// another caller or when called from inside a job.
    bool tryRunOnAll(const std::function<void()>& job) {
        if (insideJob() || !inUse_.try_lock()) return false;
        const std::lock_guard release(inUse_, std::adopt_lock);
        {
            const std::lock_guard lock(mutex_);
            job_ = &job;
            running_ = helperCount();
            ++generation_;
        }
        wake_.notify_all();
        insideJob() = true;
        job();
        insideJob() = false;
        std::unique_lock lock(mutex_);
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

    void serve() {
        insideJob() = true;
        std::uint64_t seen = 0;
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            const std::function<void()>* job = job_;
            lock.unlock();
            (*job)();
            lock.lock();
            if (--running_ == 0) finished_.notify_one();
        }
    }

    std::mutex inUse_;  ///< held by the caller of tryRunOnAll for the whole job
    std::mutex mutex_;  ///< guards the fields below
    std::condition_variable wake_, finished_;
    const std::function<void()>* job_ = nullptr;
    std::uint64_t generation_ = 0;
    unsigned running_ = 0;
    bool stopping_ = false;
    std::vector<std::jthread> threads_;  ///< last: joined before the fields above go away
};

} // namespace radiant
