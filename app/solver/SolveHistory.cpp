#include "app/solver/SolveHistory.h"

namespace radiant::app {

void SolveHistoryBuilder::append(const IterationStats& stats) {
    if (tail_.empty()) tail_.reserve(SolveHistory::kChunkSize);
    tail_.push_back(stats);
    if (tail_.size() < SolveHistory::kChunkSize) return;
    // Copying the list of pointers costs one pointer per chunk once every kChunkSize steps; it keeps
    // every published list untouched.
    auto frozen = frozen_ ? std::make_shared<SolveHistory::FrozenChunks>(*frozen_)
                          : std::make_shared<SolveHistory::FrozenChunks>();
    frozen->push_back(std::make_shared<const SolveHistory::Chunk>(std::move(tail_)));
    frozen_ = std::move(frozen);
    tail_ = {};
}

void SolveHistoryBuilder::clear() {
    frozen_.reset();
    tail_ = {};
}

std::size_t SolveHistoryBuilder::size() const {
    return (frozen_ ? frozen_->size() * SolveHistory::kChunkSize : 0) + tail_.size();
}

} // namespace radiant::app
