#pragma once
// Frame times over the last N frames; the median, not the mean, so one hitch does not move the readout.
#include <cstddef>
#include <vector>

namespace radiant::app {

class FrameStats {
public:
    explicit FrameStats(std::size_t window = 120) : capacity_(window) { samples_.reserve(window); }

    void add(double frameSeconds);
    /// Median of the recorded frame times in seconds (0 before the first frame).
    [[nodiscard]] double medianSeconds() const;
    [[nodiscard]] std::size_t count() const { return samples_.size(); }

private:
    std::size_t capacity_;
    std::size_t next_ = 0;
    std::vector<double> samples_;
};

} // namespace radiant::app
