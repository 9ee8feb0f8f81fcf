#pragma once
// The Solver panel's convergence plot: each method's residual against the iteration on a log10
// axis with ticks and labels, the tolerance as a line, one colour per method (a legend names each
// curve and the step at which it reached the tolerance), the re-solves after material edits as
// dashed curves of their own that start again at iteration 1; and "Export CSV" of all of it
// (app/solver/ConvergenceCsv.h).
#include <array>
#include <string>

#include "app/solver/Snapshot.h"

namespace radiant::app {

class ConvergencePlot {
public:
    ConvergencePlot();
    void draw(const Snapshot& snapshot);

    /// The newest segments plotted (and named in the legend); the CSV has them all.
    static constexpr std::size_t kMaxSegmentsShown = 8;

private:
    void drawExport(const Snapshot& snapshot);

    std::array<char, 512> csvPath_{};
    std::string exportMessage_;
    bool exportFailed_ = false;
};

} // namespace radiant::app
