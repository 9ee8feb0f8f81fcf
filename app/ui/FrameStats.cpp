#include "app/ui/FrameStats.h"

#include <algorithm>

namespace radiant::app {

void FrameStats::add(double frameSeconds) {
    if (samples_.size() < capacity_) {
        samples_.push_back(frameSeconds);
    } else {
        samples_[next_] = frameSeconds;
        next_ = (next_ + 1) % capacity_;
    }
}

double FrameStats::medianSeconds() const {
    if (samples_.empty()) return 0.0;
    std::vector<double> sorted = samples_;
    const std::size_t mid = sorted.size() / 2;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid), sorted.end());
    if (sorted.size() % 2 == 1) return sorted[mid];
    const double upper = sorted[mid];
    const double lower = *std::max_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid));
    return (lower + upper) / 2.0;
}

} // namespace radiant::app
