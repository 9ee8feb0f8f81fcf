#pragma once
// Progress of long work (meshing, form factors), written by the worker and read by the UI without
// locks. A request to cancel is polled by the worker between units of work.
#include <atomic>
#include <cstddef>

namespace radiant {

struct Progress {
    std::atomic<std::size_t> done{0};
    std::atomic<std::size_t> total{0};
    std::atomic<bool> cancelRequested{false};

    [[nodiscard]] double fraction() const {
        const auto t = total.load(std::memory_order_relaxed);
        return t == 0 ? 0.0 : static_cast<double>(done.load(std::memory_order_relaxed)) / static_cast<double>(t);
    }
    /// Throws radiant::Cancelled when cancellation was requested.
    void checkCancelled() const;
};

} // namespace radiant
