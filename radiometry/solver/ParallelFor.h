#pragma once
// Splits [0, count) into chunks handed out through an atomic counter to one thread per core, so
// uneven rows (a form-factor row i has n - i - 1 pairs) still balance. The threads are the shared
// WorkerPool's persistent helpers; when another caller holds the pool, fresh std::jthreads as
// before, and a call from inside a job runs on its own thread. The first exception a worker throws
// is rethrown on the calling thread after every worker has stopped.
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

/// Worker threads for parallel loops: the hardware's, at least one.
inline unsigned workerCount() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Calls body(begin, end) on disjoint chunks of at most `grain` indices covering [0, count). Inside a
/// CancellationScope of the calling thread, throws Cancelled between chunks once it is requested.
template <class Body>
void parallelFor(std::size_t count, std::size_t grain, Body&& body) {
    grain = std::max<std::size_t>(grain, 1);
    const Progress* const cancellation = CancellationScope::current();
    const std::size_t chunks = (count + grain - 1) / grain;
    const unsigned threads = static_cast<unsigned>(std::min<std::size_t>(workerCount(), chunks));
    if (threads <= 1 || WorkerPool::calledFromJob()) {
        for (std::size_t begin = 0; begin < count; begin += grain) {
            if (cancellation) cancellation->checkCancelled();
            body(begin, std::min(count, begin + grain));
        }
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr firstError;
    std::mutex errorMutex;
    const auto work = [&] {
        try {
            for (std::size_t chunk = next.fetch_add(1); chunk < chunks && !failed.load(std::memory_order_relaxed);
                 chunk = next.fetch_add(1)) {
                if (cancellation) cancellation->checkCancelled();
                const std::size_t begin = chunk * grain;
                body(begin, std::min(count, begin + grain));
            }
        } catch (...) {
            const std::lock_guard lock(errorMutex);
            if (!firstError) firstError = std::current_exception();
            failed = true;
        }
    };
    if (WorkerPool::shared().tryRunOnAll(work)) {
        if (firstError) std::rethrow_exception(firstError);
        return;
    }
    {
        std::vector<std::jthread> helpers;
        helpers.reserve(threads - 1);
        for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
        work();
    }  // the jthreads join here
    if (firstError) std::rethrow_exception(firstError);
}

} // namespace radiant
