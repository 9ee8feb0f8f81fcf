#pragma once
// The convergence plot's data: every method's last run, cut into segments, so that methods can be
// overlaid ("Gauss-Seidel reaches 1e-4 in 8 sweeps, Jacobi in 14") and a material edit starts a new
// labelled curve instead of a sawtooth on the old one.
//
// A segment is one uninterrupted stretch of one method's steps on one set of materials: the run from
// B = E, or the re-solve after a material edit (from the solution the edit found). Restarting a
// method (Reset, choosing it again, a new link tolerance) drops that method's earlier segments; a new
// scene or mesh drops every method's. Only the segment being solved grows: the earlier ones are
// frozen and shared by pointer, so publishing costs one pointer more than SolveHistory's: the
// segment being solved is the snapshot's `history` itself, not a second copy of it.
//
// Thread safety: ConvergenceRecord is an immutable value; the worker owns the ConvergenceRecorder.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "app/solver/SolveHistory.h"

namespace radiant::app {

struct SegmentInfo {
    SolverMethod method = SolverMethod::Jacobi;
    /// 0: the run from B = E; k: the re-solve after the k-th material edit since the method started.
    std::size_t index = 0;
    std::string label;  ///< for the legend: "Jacobi", "Jacobi, edit 1: light"
};

struct HistorySegment {
    SegmentInfo info;
    SolveHistory steps;  ///< step i of the segment at [i - 1]
};

/// A segment as the plot and the CSV read it: pointers into a record and a snapshot that outlive it.
struct SegmentView {
    const SegmentInfo* info = nullptr;
    const SolveHistory* steps = nullptr;
};

class ConvergenceRecord {
public:
    ConvergenceRecord() = default;
    /// The finished segments, oldest first, then the one being solved, whose steps are
    /// `currentSteps` (the snapshot's history). A current segment with no steps yet is left out.
    [[nodiscard]] std::vector<SegmentView> segments(const SolveHistory& currentSteps) const;
    [[nodiscard]] const SegmentInfo& current() const { return current_; }

private:
    friend class ConvergenceRecorder;
    ConvergenceRecord(std::shared_ptr<const std::vector<HistorySegment>> finished, SegmentInfo current)
        : finished_(std::move(finished)), current_(std::move(current)) {}
    std::shared_ptr<const std::vector<HistorySegment>> finished_;  ///< null: none
    SegmentInfo current_;
};

/// The worker's side: appends steps and cuts segments at restarts and material edits.
class ConvergenceRecorder {
public:
    explicit ConvergenceRecorder(SolverMethod method = SolverMethod::Jacobi) { clear(method); }

    void append(const IterationStats& stats) { steps_.append(stats); }
    /// The steps of the segment being solved.
    [[nodiscard]] const SolveHistoryBuilder& steps() const { return steps_; }
    /// `method` starts from B = E: its earlier segments go, the other methods' stay.
    void restart(SolverMethod method);
    /// A material of `surfaceName` changed: the steps from here on are a new segment of the same
    /// method. Edits before the first step of a segment fold into it (its label names the last). An
    /// edit that `continues` the gesture which started the segment (a slider dragged sends an edit a
    /// frame, a typed number one per digit) restarts that segment's steps: one curve per gesture,
    /// the re-solve from its final value, neither a hundred segments nor a sawtooth inside one.
    void materialEdited(const std::string& surfaceName, bool continues = false);
    /// The materials are the scene's as loaded again, and `method` starts from B = E.
    void materialsRestored(SolverMethod method);
    /// A new scene or mesh: nothing recorded is comparable any more.
    void clear(SolverMethod method);
    /// The record as it stands (shares the finished segments); the current steps are steps().snapshot().
    [[nodiscard]] ConvergenceRecord snapshot() const { return {finished_, current_}; }

private:
    void finishCurrent();
    [[nodiscard]] std::string restartLabel(SolverMethod method) const;

    std::shared_ptr<const std::vector<HistorySegment>> finished_;  ///< replaced, never modified, once shared
    SegmentInfo current_;
    SolveHistoryBuilder steps_;
    std::size_t editsSinceLoad_ = 0;  ///< material edits in effect (0: the scene as loaded)
};

} // namespace radiant::app
