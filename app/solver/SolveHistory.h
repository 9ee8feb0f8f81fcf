#pragma once
// Every step since the last reset, as the snapshots carry it. A progressive solve takes thousands of
// steps a second and the worker publishes every 12 ms, so a snapshot must not copy the whole
// history: the history is cut into chunks of kChunkSize steps, and a chunk, once full, is frozen
// (const, shared by pointer) and never changes again. Publishing copies one pointer to the list of
// frozen chunks and the partial last chunk only, whatever the history's length.
//
// Thread safety: a SolveHistory is an immutable value; everything it points to is const once
// shared. Only the worker appends, to its own SolveHistoryBuilder.
#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "radiometry/solver/Solver.h"

namespace radiant::app {

class SolveHistory {
public:
    static constexpr std::size_t kChunkSize = 1024;
    using Chunk = std::vector<IterationStats>;  ///< exactly kChunkSize entries once frozen
    using FrozenChunks = std::vector<std::shared_ptr<const Chunk>>;

    SolveHistory() = default;

    [[nodiscard]] std::size_t size() const { return frozenCount() * kChunkSize + tail_.size(); }
    [[nodiscard]] bool empty() const { return size() == 0; }
    /// Step i + 1 (the first step is at 0); i < size().
    [[nodiscard]] const IterationStats& operator[](std::size_t i) const {
        const std::size_t chunk = i / kChunkSize;
        return chunk < frozenCount() ? (*(*frozen_)[chunk])[i % kChunkSize] : tail_[i - frozenCount() * kChunkSize];
    }
    /// The last step; the history must not be empty.
    [[nodiscard]] const IterationStats& back() const { return (*this)[size() - 1]; }
    /// The full chunks, oldest first: the same pointers in every later snapshot until a reset.
    [[nodiscard]] std::span<const std::shared_ptr<const Chunk>> frozenChunks() const {
        if (!frozen_) return {};
        return *frozen_;
    }

private:
    friend class SolveHistoryBuilder;
    SolveHistory(std::shared_ptr<const FrozenChunks> frozen, Chunk tail)
        : frozen_(std::move(frozen)), tail_(std::move(tail)) {}
    [[nodiscard]] std::size_t frozenCount() const { return frozen_ ? frozen_->size() : 0; }

    std::shared_ptr<const FrozenChunks> frozen_;  ///< null while no chunk is full
    Chunk tail_;                                  ///< fewer than kChunkSize entries
};

/// The worker's growing history; hands out immutable SolveHistory values.
class SolveHistoryBuilder {
public:
    void append(const IterationStats& stats);
    void clear();
    [[nodiscard]] std::size_t size() const;
    /// Shares the frozen chunks and copies the partial one: cost independent of size().
    [[nodiscard]] SolveHistory snapshot() const { return SolveHistory(frozen_, tail_); }

private:
    // Replaced, never modified, when a chunk freezes: earlier snapshots keep the list they were given.
    std::shared_ptr<const SolveHistory::FrozenChunks> frozen_;
    SolveHistory::Chunk tail_;
};

} // namespace radiant::app
