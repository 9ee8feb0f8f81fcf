#pragma once
// Splits [0, count) into chunks handed out through an atomic counter to one thread per core, so
// uneven rows (a form-factor row i has n - i - 1 pairs) still balance. The threads are the shared
// WorkerPool's persistent helpers. When another caller holds the pool (the lab's second solver), or
// the call comes from inside a job, the loop runs on the calling thread alone: the pool's threads
// already fill the cores, and more threads than cores only took turns with the window's drawing
// threads (issue #16's comparison frames). The first exception a worker throws is rethrown on the
// calling thread after every worker has stopped.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>

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
    const auto serially = [&] {
        for (std::size_t begin = 0; begin < count; begin += grain) {
            if (cancellation) cancellation->checkCancelled();
            body(begin, std::min(count, begin + grain));
        }
    };
    if (threads <= 1 || WorkerPool::calledFromJob()) {
        serially();
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
    if (!WorkerPool::shared().tryRunOnAll(work)) {
        serially();
        return;
    }
    if (firstError) std::rethrow_exception(firstError);
}

} // namespace radiant
