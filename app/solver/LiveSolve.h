#pragma once
// What the panels share: the solver thread to send commands to, and the snapshot this frame shows.
// The lab replaces `current` once at the start of every frame (one atomic load), so every panel
// draws the same solve state and none of them waits for the worker.
//
// Comparison mode (two methods side by side, Comparison.h): a second solver thread, owned here,
// solves the same scene by another method or at another meshing. Every command sent goes to both
// (translated by commandForSecond), so panels, shortcuts and lessons drive the pair as they drive one.
#include <memory>
#include <optional>
#include <utility>

#include "app/solver/Comparison.h"
#include "app/solver/MaterialEditHistory.h"
#include "app/solver/SolverThread.h"

namespace radiant::app {

struct LiveSolve {
    explicit LiveSolve(SolverThread& solverThread) : thread(solverThread), current(solverThread.snapshot()) {}
    ~LiveSolve();
    LiveSolve(const LiveSolve&) = delete;
    LiveSolve& operator=(const LiveSolve&) = delete;

    void send(SolverCommand command);
    /// This frame's solve is running or has converged: a change of what is solved (a material, the
    /// mesh, the grouping) then runs on to the new answer without a click, while a paused or stepped
    /// solve stays as the teacher left it (the next step shows the change).
    [[nodiscard]] bool resumesAfterChange() const {
        return current->running ||
               (current->stats.iteration > 0 && current->stats.residual < current->tolerance);
    }
    /// send(command), then Run when resumesAfterChange() held before it.
    void sendAndResume(SolverCommand command);
    /// Takes the newest snapshots; true when the first's differs from the one held before.
    bool refresh();
    [[nodiscard]] const Snapshot& snapshot() const { return *current; }
    /// Either solver running (Space pauses both, or runs both).
    [[nodiscard]] bool running() const { return current->running || (secondCurrent && secondCurrent->running); }

    /// Starts the second solver on the first's scene (as edited), both from B = E (the first is
    /// reset, so their curves start together), running when the first was told to run; or stops and
    /// drops it. B's method, when it is A's on the same mesh, becomes A's partner in the lecture
    /// (Jacobi for Gauss-Seidel, Gauss-Seidel for any other).
    void compare(bool on);
    [[nodiscard]] bool comparing() const { return second != nullptr; }
    /// Comparison mode: B is running, building, or has published a snapshot newer than this frame's.
    [[nodiscard]] bool secondChanging() const {
        return second && (secondCurrent->running || second->activity() != SolverActivity::Idle ||
                          second->snapshot()->generation != secondCurrent->generation);
    }
    /// B's method and meshing (sent to the second solver when they change) and the view.
    void setComparison(const ComparisonSettings& settings);
    [[nodiscard]] const ComparisonSettings& comparison() const { return comparison_; }

    SolverThread& thread;
    std::shared_ptr<const Snapshot> current;  ///< never null
    /// Undo and redo of material edits, whoever made them (panel, lesson, session): main thread only.
    MaterialEditHistory materialEdits;
    std::unique_ptr<SolverThread> second;     ///< comparison mode's solver B; null when off
    std::shared_ptr<const Snapshot> secondCurrent;  ///< B's snapshot this frame; null when off

private:
    ComparisonSettings comparison_;
    /// The last scene, meshing and tolerances sent (perhaps still queued): what B starts from.
    std::shared_ptr<const Scene> sentScene_;
    std::optional<MeshingOptions> sentMeshing_;
    std::optional<double> sentTolerance_, sentLinkTolerance_;
    std::optional<SolverMethod> sentMethod_;
    std::optional<GroupingMode> groupingSent_;  ///< the last SetGrouping's, for B
    bool runSent_ = false;  ///< the last of Run and Pause sent was Run
};

} // namespace radiant::app
