#pragma once
// Runs a loop over both cores (or however many there are): the hierarchical solver's refinement and
// gathering are independent per link. Work is handed out in chunks from an atomic counter, because
// links near the light cost many more rays than the rest. The shared WorkerPool's sleeping helpers run
// it (a refinement step makes dozens of short parallel passes; starting threads for each cost more
// than some passes). When another caller holds the pool (the lab's second solver), the loop runs on
// the calling thread alone, as thread 0: the pool's threads already fill the cores (ParallelFor.h).
// Fresh threads only where more are asked for than the pool has (tests of thread counts).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "radiometry/common/CancellationScope.h"
#include "radiometry/solver/WorkerPool.h"

namespace radiant {

/// Number of worker threads the hierarchical solvers use.
inline unsigned hierarchicalThreadCount() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Calls body(begin, end, thread) over [0, count) in chunks; thread < threads. The first exception
/// thrown by a body is rethrown on the calling thread once every worker has stopped. Inside a
/// CancellationScope of the calling thread, throws Cancelled between chunks once it is requested.
template <class Body>
void parallelChunks(std::size_t count, unsigned threads, std::size_t chunk, Body&& body) {
    if (count == 0) return;
    const Progress* const cancellation = CancellationScope::current();
    if (threads <= 1 || count <= chunk) {
        for (std::size_t begin = 0; begin < count; begin += chunk) {
            if (cancellation) cancellation->checkCancelled();
            body(begin, std::min(count, begin + chunk), 0u);
        }
        return;
    }
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto work = [&](unsigned thread) {
        try {
            for (;;) {
                const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
                if (begin >= count) return;
                if (cancellation) cancellation->checkCancelled();
                body(begin, std::min(count, begin + chunk), thread);
            }
        } catch (...) {
            const std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
            next.store(count, std::memory_order_relaxed);
        }
    };
    WorkerPool& pool = WorkerPool::shared();
    std::atomic<unsigned> nextThread{0};
    const auto job = [&] {
        const unsigned thread = nextThread.fetch_add(1, std::memory_order_relaxed);
        if (thread < threads) work(thread);
    };
    if (pool.helperCount() + 1 < threads) {
        std::vector<std::jthread> workers;
        workers.reserve(threads - 1);
        for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work, t);
        work(0);
    } else if (!pool.tryRunOnAll(job)) {
        work(0);
    }  // joins
    if (failure) std::rethrow_exception(failure);
}

} // namespace radiant
