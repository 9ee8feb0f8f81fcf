#pragma once
// The Solver panel's convergence plot: each method's residual against the iteration on a log10
// axis with ticks and labels, the tolerance as a line, one colour per method (a legend names each
// curve and the step at which it reached the tolerance), the re-solves after material edits as
// dashed curves of their own that start again at iteration 1; and "Export CSV" of all of it
// (app/solver/ConvergenceCsv.h).
#include <array>
#include <string>
#include <vector>

#include "app/solver/Snapshot.h"

namespace radiant::app {

class ConvergencePlot {
public:
    ConvergencePlot();
    /// With `second` (comparison mode), the current run of each solver, in the sides' colours.
    void draw(const Snapshot& snapshot, const Snapshot* second = nullptr);

    /// The newest segments plotted (and named in the legend); the CSV has them all.
    static constexpr std::size_t kMaxSegmentsShown = 8;

private:
    struct Curve {
        const SolveHistory* steps;
        SolverMethod method;
        std::string label;
        unsigned colour;  ///< ImU32
        bool dashed;      ///< a re-solve after a material edit
    };
    static std::vector<Curve> curves(const Snapshot& snapshot, const Snapshot* second);
    void drawExport(const Snapshot& snapshot);

    std::array<char, 512> csvPath_{};
    std::string exportMessage_;
    bool exportFailed_ = false;
};

} // namespace radiant::app
