// ctest-labels: threads;stress
// Concurrency stress: a seeded random storm of commands to a SolverThread running the real solvers on
// a coarse Cornell box, while a reader takes snapshots at a display's pace and checks each one, under a
// watchdog that measures progress rather than time. Run under ThreadSanitizer by scripts/test (labels
// "threads" and "stress"); see docs/RELIABILITY.md.
#include <doctest/doctest.h>

#include <cxxabi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <future>
#include <iomanip>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <utility>
#include <variant>
#include <vector>

#include <glm/common.hpp>

#include "app/solver/SolverThread.h"
#include "radiometry/scene/BuiltinScenes.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// Every method in the table, so a new one is stormed too.
SolverMethod methodNumber(std::size_t i) { return solverMethods()[i % solverMethods().size()].method; }
/// Coarse enough that a form-factor build takes milliseconds (tens of patches), so thousands of
/// commands with hundreds of rebuilds finish in seconds, even under ThreadSanitizer.
constexpr double kPatchAreas[] = {0.12, 0.2, 0.35};
constexpr double kTolerances[] = {1e-1, 1e-2, 1e-3};
/// Both the thread and the fresh solve stop below this; the comparison's bound scales with it.
constexpr double kFinalTolerance = 1e-3;
/// The watchdog's limit: far longer than any one command takes under the sanitizers on a loaded
/// machine (a coarse form-factor build takes milliseconds), so only a thread that is stuck hits it.
constexpr auto kStallLimit = std::chrono::seconds(60);

/// Small, cheap solvers: few visibility rays, coarse hierarchical elements.
SolverOptions cheapOptions() {
    SolverOptions options;
    options.formFactors.visibilityRays = 4;
    options.formFactors.accuracy = 1e-2;
    options.linkEpsilon = 1e-2;
    options.minElementArea = 0.02;
    return options;
}

bool allBandsFinite(const std::vector<Rgb>& values) {
    return std::all_of(values.begin(), values.end(),
                       [](const Rgb& b) { return std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z); });
}

/// What the storm's own threads (sender and reader) have done, for the watchdog, which reads it
/// while they run.
struct StormProgress {
    std::atomic<std::uint64_t> commandsSent{0};
    std::atomic<const char*> senderPhase{"starting"};
    std::atomic<std::uint64_t> readerLastGeneration{0};
    std::atomic<std::uint64_t> readerReads{0};
};

/// Takes snapshots until told to stop and records the first inconsistency it sees. It reads at a
/// display's pace, not as fast as it can: a reader spinning on the snapshot took 26-33 million
/// snapshots per seed under ThreadSanitizer, and a core the worker (at nice 10) then waited for.
class SnapshotReader {
public:
    /// At most 2500 snapshots a second. The lab takes one a frame; the worker publishes once per
    /// command and at most every 12 ms while stepping, so this still sees most publications.
    static constexpr auto kPause = std::chrono::microseconds(400);

    SnapshotReader(const SolverThread& thread, StormProgress& progress)
        : progress_(progress), worker_([this, &thread](std::stop_token stop) { readUntil(stop, thread); }) {}

    void stop() {
        worker_.request_stop();
        worker_.join();
    }
    [[nodiscard]] const std::string& firstProblem() const { return problem_; }  // after stop()
    [[nodiscard]] std::size_t distinctMeshes() const { return meshes_.size(); }  // after stop()

private:
    void readUntil(const std::stop_token& stop, const SolverThread& thread) {
        std::uint64_t lastGeneration = 0, lastMeshGeneration = 0;
        while (!stop.stop_requested() && problem_.empty()) {
            const std::shared_ptr<const Snapshot> s = thread.snapshot();
            std::ostringstream why;
            if (s->generation < lastGeneration) why << "generation went back from " << lastGeneration << " to " << s->generation;
            if (s->meshGeneration < lastMeshGeneration)
                why << "mesh generation went back from " << lastMeshGeneration << " to " << s->meshGeneration;
            const std::size_t patches = s->mesh ? s->mesh->size() : 0;
            if (!s->radiosity.empty() && s->radiosity.size() != patches)
                why << "radiosity has " << s->radiosity.size() << " values for " << patches << " patches";
            if (!allBandsFinite(s->radiosity)) why << "radiosity is not finite";
            if (s->mesh && (!s->scene || s->mesh->surfaceFirstPatch.size() != s->scene->surfaces.size() + 1))
                why << "mesh and scene disagree on the surface count";
            // One mesh per mesh generation: the mesh pointer changes exactly when the generation does.
            const auto [known, inserted] = meshes_.emplace(s->meshGeneration, s->mesh);
            if (!inserted && known->second != s->mesh) why << "mesh generation " << s->meshGeneration << " has two meshes";
            lastGeneration = s->generation;
            lastMeshGeneration = s->meshGeneration;
            progress_.readerLastGeneration.store(lastGeneration, std::memory_order_relaxed);
            progress_.readerReads.fetch_add(1, std::memory_order_relaxed);
            problem_ = why.str();
            std::this_thread::sleep_for(kPause);
        }
    }

    StormProgress& progress_;
    std::string problem_;
    std::map<std::uint64_t, std::shared_ptr<const PatchMesh>> meshes_;  // kept alive: no pointer reuse
    std::jthread worker_;  // last: starts after the members it writes exist
};

/// The name of the alternative at `index` of SolverCommand, from its type: a new command needs no
/// entry here.
template <std::size_t... I>
std::string commandName(std::size_t index, std::index_sequence<I...>) {
    const auto nameOf = [](const char* mangled) {
        int status = 0;
        const std::unique_ptr<char, void (*)(void*)> readable(abi::__cxa_demangle(mangled, nullptr, nullptr, &status),
                                                               std::free);
        const std::string text = status == 0 ? readable.get() : mangled;
        const std::size_t colon = text.rfind(':');
        return colon == std::string::npos ? text : text.substr(colon + 1);
    };
    const std::string names[] = {nameOf(typeid(std::variant_alternative_t<I, SolverCommand>).name())...};
    return index < sizeof...(I) ? names[index] : "none yet";
}

struct StormResult {
    std::shared_ptr<const Snapshot> final;
    std::string readerProblem;
    std::size_t snapshotsRead = 0;
    std::size_t meshesSeen = 0;
    SolverMethod finalMethod = SolverMethod::Jacobi;
};

/// A seeded storm: the solver thread, the reader, and the sender (run(), on a thread of its own).
class Storm {
public:
    Storm(std::uint64_t seed, int commands, SolverFactory factory = {})
        : seed_(seed), commands_(commands), thread_(cheapOptions(), std::move(factory)), reader_(thread_, progress_) {}

    StormResult run();

    /// Grows whenever the worker takes a command or publishes a snapshot: the watchdog's measure.
    [[nodiscard]] std::uint64_t progressMark() const {
        const SolverThread::Heartbeat beat = thread_.heartbeat();
        return beat.commandsTaken + beat.generationPublished;
    }

    /// What each thread was last doing, for the watchdog's report.
    [[nodiscard]] std::string describe() const {
        const SolverThread::Heartbeat beat = thread_.heartbeat();
        const Progress& build = thread_.progress();
        std::ostringstream text;
        text << "sender: " << progress_.senderPhase.load() << ", " << progress_.commandsSent.load()
             << " commands sent; worker: " << beat.commandsTaken << " commands taken, the last a "
             << commandName(beat.lastCommand, std::make_index_sequence<std::variant_size_v<SolverCommand>>{}) << ", "
             << activityName(thread_.activity()) << " (progress " << build.done.load() << " of " << build.total.load()
             << "), generation " << beat.generationPublished << " published; reader: last saw generation "
             << progress_.readerLastGeneration.load() << ", " << progress_.readerReads.load() << " snapshots read";
        return text.str();
    }

private:
    std::uint64_t seed_;
    int commands_;
    StormProgress progress_;
    SolverThread thread_;
    SnapshotReader reader_;  // after the thread it reads and the progress it writes
};

StormResult Storm::run() {
    std::mt19937_64 random(seed_);
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
    const auto send = [&](SolverCommand command) {
        thread_.send(std::move(command));
        progress_.commandsSent.fetch_add(1, std::memory_order_relaxed);
    };

    auto scene = std::make_shared<const Scene>(makeCornellBox());
    std::size_t light = 0;
    for (std::size_t s = 0; s < scene->surfaces.size(); ++s)
        if (scene->materials[scene->surfaces[s].material].exitance.value().x > 0) light = s;

    progress_.senderPhase.store("sending");
    send(command::LoadScene{scene, MeshingOptions{kPatchAreas[0], 100'000}});
    for (int c = 0; c < commands_; ++c) {
        const std::size_t kind = pick(100);
        if (kind < 20) {
            send(command::Step{1 + pick(3)});
        } else if (kind < 32) {
            send(command::Run{});
        } else if (kind < 44) {
            send(command::Pause{});
        } else if (kind < 68) {
            // Mostly valid materials; now and then a surface that does not exist (must become an error).
            const std::size_t surface = pick(20) == 0 ? scene->surfaces.size() + pick(3) : pick(scene->surfaces.size());
            const Rgb reflectance(uniform(0, 0.8), uniform(0, 0.8), uniform(0, 0.8));
            const Rgb exitance = surface == light ? Rgb(uniform(1, 20), uniform(1, 20), uniform(1, 20)) : Rgb(0.0);
            send(command::SetMaterial{surface, reflectance, ExitanceRgb(exitance)});
        } else if (kind < 74) {
            send(command::SetMethod{methodNumber(pick(solverMethods().size()))});
        } else if (kind < 78) {
            send(command::Remesh{MeshingOptions{kPatchAreas[pick(std::size(kPatchAreas))], 100'000}});
        } else if (kind < 88) {
            send(command::Reset{});
        } else {
            // Now and then an invalid tolerance (must become an error, not a stuck solver).
            send(command::SetTolerance{pick(10) == 0 ? 0.0 : kTolerances[pick(std::size(kTolerances))]});
        }
        // Bursts, then short gaps, so the worker is caught both mid-build and mid-solve.
        if (pick(16) == 0) std::this_thread::sleep_for(std::chrono::microseconds(pick(1500)));
    }

    // The final settings. Hierarchical refinement depends on the radiosity it has seen, so its links
    // after a storm differ from a fresh solve's by design: those methods are rebuilt (switch away
    // and back) before the comparison. The gathering and shooting solvers keep the state the storm
    // left them, so material edits on a live solver are what the comparison checks.
    StormResult result;
    result.finalMethod = methodNumber(pick(solverMethods().size()));
    if (methodInfo(result.finalMethod).traits.links) send(command::SetMethod{SolverMethod::Jacobi});
    send(command::SetMethod{result.finalMethod});
    send(command::SetTolerance{kFinalTolerance});
    send(command::Run{});
    progress_.senderPhase.store("waiting until the worker is idle");
    thread_.waitUntilIdle();
    progress_.senderPhase.store("done");
    reader_.stop();
    result.final = thread_.snapshot();
    result.readerProblem = reader_.firstProblem();
    result.snapshotsRead = progress_.readerReads.load();
    result.meshesSeen = reader_.distinctMeshes();
    return result;
}

/// A storm run on a thread of its own under a watchdog that measures progress, not time: a slow
/// machine (a parallel build, the sanitizers, the worker at nice 10 behind other work) only makes the
/// storm take longer. The watchdog gives up only when the worker has taken no command and published
/// no snapshot for `stallLimit`, and then says what each thread was doing.
struct WatchedStorm {
    std::shared_ptr<Storm> storm;
    std::future<StormResult> result;
    std::string stallReport;  ///< empty when the storm finished
    std::chrono::steady_clock::duration elapsed{};
    std::chrono::steady_clock::duration longestWait{};  ///< the longest the watchdog saw no progress
};

/// Starts the storm on a thread of its own; watch() then waits for it.
WatchedStorm launchStorm(const std::shared_ptr<Storm>& storm) {
    return {storm, std::async(std::launch::async, [storm] { return storm->run(); }), {}, {}, {}};
}

/// Waits for a launched storm, or until it has made no progress for `stallLimit`.
void watch(WatchedStorm& watched, std::chrono::steady_clock::duration stallLimit) {
    const std::shared_ptr<Storm>& storm = watched.storm;
    const auto started = std::chrono::steady_clock::now();
    auto lastProgress = started;
    std::uint64_t mark = storm->progressMark();
    while (watched.result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
        const auto now = std::chrono::steady_clock::now();
        if (const std::uint64_t newMark = storm->progressMark(); newMark != mark) {
            mark = newMark;
            watched.longestWait = std::max(watched.longestWait, now - lastProgress);
            lastProgress = now;
        } else if (now - lastProgress >= stallLimit) {
            std::ostringstream report;
            report << "no command taken and no snapshot published for " << std::fixed << std::setprecision(1)
                   << std::chrono::duration<double>(now - lastProgress).count() << " s: " << storm->describe();
            watched.stallReport = report.str();
            break;
        }
    }
    watched.elapsed = std::chrono::steady_clock::now() - started;
}

WatchedStorm watchStorm(const std::shared_ptr<Storm>& storm, std::chrono::steady_clock::duration stallLimit) {
    WatchedStorm watched = launchStorm(storm);
    watch(watched, stallLimit);
    return watched;
}

/// sum_i A_i |a_i - b_i| per band, W.
Rgb areaWeightedDifference(const PatchMesh& mesh, const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    Rgb sum(0.0);
    for (std::size_t i = 0; i < mesh.size(); ++i) sum += mesh.patches[i].area * glm::abs(a[i] - b[i]);
    return sum;
}

void checkStorm(std::uint64_t seed, int commands) {
    WatchedStorm watched = watchStorm(std::make_shared<Storm>(seed, commands), kStallLimit);
    if (!watched.stallReport.empty()) {
        const std::string report = watched.stallReport;
        // Leak the storm on purpose: destroying it would join the stuck threads and hang the run.
        new WatchedStorm(std::move(watched));
        FAIL("seed " << seed << ": " << report);
    }
    const StormResult result = watched.result.get();
    INFO("seed " << seed << ", final method " << methodName(result.finalMethod));
    CHECK_MESSAGE(result.readerProblem.empty(), result.readerProblem);
    CHECK(result.snapshotsRead > 0);
    MESSAGE("seed " << seed << ": " << result.snapshotsRead << " snapshots read, " << result.meshesSeen
                    << " mesh generations, " << std::chrono::duration<double>(watched.elapsed).count()
                    << " s, the longest without progress " << std::chrono::duration<double>(watched.longestWait).count()
                    << " s");

    const Snapshot& s = *result.final;
    REQUIRE_MESSAGE(s.error.empty(), s.error);
    REQUIRE(s.mesh);
    REQUIRE(s.scene);
    REQUIRE(s.method == result.finalMethod);
    REQUIRE(s.radiosity.size() == s.mesh->size());
    CHECK(!s.running);
    REQUIRE(s.stats.residual < kFinalTolerance);

    // A fresh solve of the same scene (materials as edited), mesh and method to the same tolerance.
    const std::unique_ptr<Solver> fresh = makeSolver(result.finalMethod, *s.scene, *s.mesh, cheapOptions());
    for (int k = 0; k < 100'000 && fresh->lastStats().residual >= kFinalTolerance; ++k) fresh->step();
    REQUIRE(fresh->lastStats().residual < kFinalTolerance);

    // Both are within the tolerance of the same exact solution: with residual r (as a fraction of
    // emitted power P_b), sum_i A_i |B_i - B*_i| <= r P_b / (1 - rho_max), because the operator
    // rho F has area-weighted L1 norm <= rho_max (reciprocity: sum_i A_i F_ij <= A_j).
    double rhoMax = 0;
    Rgb emitted(0.0);
    for (std::size_t i = 0; i < s.mesh->size(); ++i) {
        const Material& m = s.scene->materials[s.scene->surfaces[s.mesh->patches[i].surface].material];
        rhoMax = std::max({rhoMax, m.reflectance.x, m.reflectance.y, m.reflectance.z});
        emitted += s.mesh->patches[i].area * m.exitance.value();
    }
    const Rgb difference = areaWeightedDifference(*s.mesh, s.radiosity, fresh->solution());
    for (int band = 0; band < 3; ++band) {
        const double bound = 2 * kFinalTolerance * emitted[band] / (1 - rhoMax);
        CHECK_MESSAGE(difference[band] <= bound, "band " << band << ": sum A |B - B_fresh| = " << difference[band]
                                                         << " W, bound " << bound << " W");
    }
}

/// The seeds to storm: RADIANT_STRESS_SEEDS="4,5,6" picks others (to hunt a deadlock under load, see
/// docs/RELIABILITY.md); by default 1, 2, 3.
std::vector<std::uint64_t> stormSeeds() {
    std::vector<std::uint64_t> seeds;
    if (const char* list = std::getenv("RADIANT_STRESS_SEEDS")) {
        std::istringstream in(list);
        std::string item;
        while (std::getline(in, item, ','))
            if (!item.empty()) seeds.push_back(std::stoull(item));
    }
    if (seeds.empty()) seeds = {1, 2, 3};
    return seeds;
}

/// A test-only deadlock: the solver build numbered `stuckAt` blocks until released, deaf to
/// cancellation, as a worker waiting on a lock nobody will give up would. Released only after the
/// watchdog has spoken, so the threads still end and join.
class StuckBuild {
public:
    explicit StuckBuild(int stuckAt)
        : stuckAt_(stuckAt), entered_(enter_.get_future().share()), released_(release_.get_future().share()) {}

    SolverFactory factory() {
        return [this](SolverMethod method, const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                      Progress* progress) {
            if (++builds_ == stuckAt_) {
                enter_.set_value();
                released_.wait();
            }
            return makeSolver(method, scene, mesh, options, progress);
        };
    }
    /// True once the worker is inside the stuck build (and so can make no more progress).
    [[nodiscard]] bool entered() const {
        return entered_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    }
    void release() { release_.set_value(); }

private:
    int stuckAt_;
    std::atomic<int> builds_{0};
    std::promise<void> enter_;
    std::shared_future<void> entered_;
    std::promise<void> release_;
    std::shared_future<void> released_;
};

} // namespace

TEST_SUITE("stress") {

TEST_CASE("thousands of random commands: every snapshot consistent, the end equals a fresh solve") {
    // Three seeds end in a gathering, a shooting and a rebuilt hierarchical solver (final methods
    // Gauss-Seidel, progressive, hierarchical); each storm is reproducible from its seed.
    for (const std::uint64_t seed : stormSeeds()) checkStorm(seed, 2000);
}

TEST_CASE("a worker stuck mid-build is reported by the watchdog with every thread's state") {
    // The real limit is 60 s; a short one keeps this test fast. The report must name what the stuck
    // worker was doing (a solver build: form factors), the command it took last, and how far the
    // sender and the reader got. The short limit is armed only once the worker is inside the stuck
    // build: armed at once, it fired on a loaded machine (load ~10, the worker at nice 10) while the
    // worker was still slowly meshing the first scene ("1 commands taken, the last a LoadScene,
    // meshing"), a slow worker taken for a stuck one, and the report named no form factors. A storm
    // that ends without reaching the stuck build fails the REQUIRE below rather than hangs.
    constexpr auto kShortStallLimit = std::chrono::seconds(2);
    StuckBuild stuck(3);
    const auto storm = std::make_shared<Storm>(1, 300, stuck.factory());
    WatchedStorm watched = launchStorm(storm);
    // Until then the real limit watches: a storm that stops making progress before the stuck build
    // is a failure of its own, reported here rather than by ctest's timeout.
    constexpr auto kRealStallLimit = std::chrono::seconds(60);
    std::uint64_t mark = storm->progressMark();
    auto lastProgress = std::chrono::steady_clock::now();
    while (!stuck.entered() && watched.result.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) {
        const auto now = std::chrono::steady_clock::now();
        if (const std::uint64_t newMark = storm->progressMark(); newMark != mark) {
            mark = newMark;
            lastProgress = now;
        }
        if (now - lastProgress >= kRealStallLimit) {
            stuck.release();
            FAIL("no progress for 60 s before the stuck build: " << storm->describe());
        }
    }
    REQUIRE_MESSAGE(stuck.entered(), "the storm ended without reaching the stuck build");
    watch(watched, kShortStallLimit);
    stuck.release();
    const StormResult result = watched.result.get();  // released: the storm ends and its threads join

    MESSAGE(watched.stallReport);
    REQUIRE_FALSE(watched.stallReport.empty());
    CHECK(watched.elapsed >= kShortStallLimit);
    CHECK(watched.elapsed < std::chrono::seconds(90));
    CHECK(watched.stallReport.find("worker: ") != std::string::npos);
    CHECK(watched.stallReport.find("computing form factors") != std::string::npos);
    CHECK(watched.stallReport.find("the last a none yet") == std::string::npos);
    CHECK(watched.stallReport.find("reader: last saw generation ") != std::string::npos);
    CHECK(watched.stallReport.find("sender: ") != std::string::npos);
    CHECK(result.readerProblem.empty());
}

} // TEST_SUITE
