#pragma once
// Solver: the method, Run/Pause, Step, Step N, Reset, the tolerance and (hierarchical) the link
// tolerance; the last step's numbers (iteration, residual, unshot power, links, time), the
// convergence plot (ConvergencePlot.h: every method's run overlaid, CSV export) and the step times.
#include <vector>

#include "app/panels/ConvergencePlot.h"
#include "app/panels/Panel.h"
#include "app/solver/LiveSolve.h"

namespace radiant::app {

class SolverPanel final : public Panel {
public:
    explicit SolverPanel(LiveSolve& live) : live_(live) {}

    [[nodiscard]] const char* title() const override { return "Solver"; }
    void draw() override;

private:
    void drawControls(const Snapshot& snapshot);
    /// Comparison mode: on/off, B's method and meshing, side by side or difference.
    void drawComparison();
    void drawStats(const Snapshot& snapshot);
    void drawStepTimes(const Snapshot& snapshot);

    LiveSolve& live_;
    int stepCount_ = 10;
    float toleranceExponent_ = -4.0f;  ///< log10 of the tolerance, as the slider shows it
    bool editingTolerance_ = false;
    float linkToleranceExponent_ = -4.0f;  ///< log10 of the hierarchical link tolerance
    bool editingLinkTolerance_ = false;
    ConvergencePlot convergence_;
    std::vector<float> plotValues_;    ///< scratch for PlotLines
};

} // namespace radiant::app
