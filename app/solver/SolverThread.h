#pragma once
// The worker that owns the radiosity solver. The UI sends commands through a queue and reads the
// newest immutable Snapshot each frame; neither side ever waits for the other's long work.
// Meshing and solver construction (form factors, links) report progress and are cancelled when a
// newer command makes them pointless (another scene, mesh or method).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "app/solver/SolverCommand.h"
#include "app/solver/Snapshot.h"
#include "radiometry/common/Progress.h"

namespace radiant::app {

using SolverFactory = std::function<std::unique_ptr<Solver>(SolverMethod, const Scene&, const PatchMesh&,
                                                            const SolverOptions&, Progress*)>;

class SolverThread {
public:
    /// `factory` builds solvers (makeSolver by default; tests inject their own).
    explicit SolverThread(SolverOptions options = {}, SolverFactory factory = {});
    ~SolverThread();
    SolverThread(const SolverThread&) = delete;
    SolverThread& operator=(const SolverThread&) = delete;

    /// Queues a command; returns at once.
    void send(SolverCommand command);
    /// The newest published snapshot; never blocks on the worker's work.
    [[nodiscard]] std::shared_ptr<const Snapshot> snapshot() const;
    /// Progress of the current long work (meshing or form factors), for a progress bar.
    [[nodiscard]] const Progress& progress() const { return progress_; }
    [[nodiscard]] SolverActivity activity() const { return activity_.load(std::memory_order_relaxed); }
    /// Blocks until every command sent so far has been applied and the worker is idle or only
    /// running; for tests and the command line, never for the UI.
    void waitUntilIdle();

    /// What a watchdog reads to tell a slow worker from a stuck one: both counts grow while the
    /// worker makes progress, however slowly. Relaxed reads; nothing waits on them.
    struct Heartbeat {
        std::uint64_t commandsTaken = 0;       ///< off the queue, since the thread started
        std::uint64_t generationPublished = 0; ///< the newest snapshot's generation
        std::size_t lastCommand = std::variant_npos;  ///< SolverCommand::index() of the last one taken
    };
    [[nodiscard]] Heartbeat heartbeat() const;

private:
    struct State;
    void workerLoop(const std::stop_token& stop);
    void apply(State& state, SolverCommand& command);
    void ensureSolver(State& state);
    /// After a new mesh or grouping: the default method unless the user picked one, a fresh solver
    /// and history, published at once.
    void startNewSystem(State& state);
    /// The current mesh's unknowns (its patch groups or its patches) and, unless the user picked
    /// one, the method, as `radiant solve` chooses them at --max-patch-area (DefaultGrouping.h).
    static void chooseUnknowns(State& state);
    void publish(State& state);
    /// Adds what the display's overlays need (links, importance) to a snapshot being published.
    static void publishOverlays(State& state, Snapshot& s);
    [[nodiscard]] static bool cancelsLongWork(const SolverCommand& command, SolverActivity activity);
    void requeueMeshingUnlessSuperseded(const MeshingOptions& meshing);

    SolverOptions options_;
    SolverFactory factory_;
    Progress progress_;
    std::atomic<SolverActivity> activity_{SolverActivity::Idle};
    std::atomic<std::uint64_t> commandsTaken_{0};
    std::atomic<std::uint64_t> generationPublished_{0};
    std::atomic<std::size_t> lastCommand_{std::variant_npos};

    mutable std::mutex queueMutex_;
    std::condition_variable_any queueChanged_;
    std::deque<SolverCommand> queue_;
    bool workerBusy_ = false;  ///< guarded by queueMutex_: applying a command or stepping
    std::condition_variable_any idle_;

    // The newest snapshot. The mutex guards only the pointer copy (nanoseconds), never the worker's
    // work; libstdc++ 12's std::atomic<std::shared_ptr> would do the same with a lock bit that
    // ThreadSanitizer cannot see.
    mutable std::mutex publishedMutex_;
    std::shared_ptr<const Snapshot> published_;
    std::jthread worker_;  // last: started after everything it uses exists
};

} // namespace radiant::app
