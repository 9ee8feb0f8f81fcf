#pragma once
// What the panels share: the solver thread to send commands to, and the snapshot this frame shows.
// The lab replaces `current` once at the start of every frame (one atomic load), so every panel
// draws the same solve state and none of them waits for the worker.
#include <memory>
#include <utility>

#include "app/solver/MaterialEditHistory.h"
#include "app/solver/SolverThread.h"

namespace radiant::app {

struct LiveSolve {
    explicit LiveSolve(SolverThread& solverThread) : thread(solverThread), current(solverThread.snapshot()) {}

    void send(SolverCommand command) { thread.send(std::move(command)); }
    /// Takes the newest snapshot; true when it differs from the one held before.
    bool refresh() {
        std::shared_ptr<const Snapshot> newest = thread.snapshot();
        const bool changed = newest->generation != current->generation;
        current = std::move(newest);
        return changed;
    }
    [[nodiscard]] const Snapshot& snapshot() const { return *current; }

    SolverThread& thread;
    std::shared_ptr<const Snapshot> current;  ///< never null
    /// Undo and redo of material edits, whoever made them (panel, lesson, session): main thread only.
    MaterialEditHistory materialEdits;
};

} // namespace radiant::app
