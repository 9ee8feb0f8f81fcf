// ctest-labels: threads;stress
// Concurrency stress: a seeded random storm of commands to a SolverThread running the real solvers on
// a coarse Cornell box, while a reader takes snapshots as fast as it can and checks each one. Run
// under ThreadSanitizer by scripts/test (label "threads"); see docs/RELIABILITY.md.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glm/common.hpp>

#include "app/solver/SolverThread.h"
#include "radiometry/scene/BuiltinScenes.h"

using namespace radiant;
using namespace radiant::app;

namespace {

constexpr SolverMethod kMethods[] = {SolverMethod::Jacobi, SolverMethod::GaussSeidel, SolverMethod::Progressive,
                                     SolverMethod::Hierarchical, SolverMethod::Importance};
/// Coarse enough that a form-factor build takes milliseconds (tens of patches), so thousands of
/// commands with hundreds of rebuilds finish in seconds, even under ThreadSanitizer.
constexpr double kPatchAreas[] = {0.12, 0.2, 0.35};
constexpr double kTolerances[] = {1e-1, 1e-2, 1e-3};
/// Both the thread and the fresh solve stop below this; the comparison's bound scales with it.
constexpr double kFinalTolerance = 1e-3;

/// Small, cheap solvers: few visibility rays, coarse hierarchical elements.
SolverOptions cheapOptions() {
    SolverOptions options;
    options.formFactors.visibilityRays = 4;
    options.formFactors.accuracy = 1e-2;
    options.linkEpsilon = 1e-2;
    options.minElementArea = 0.02;
    return options;
}

bool allFinite(const std::vector<Rgb>& values) {
    return std::all_of(values.begin(), values.end(),
                       [](const Rgb& b) { return std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z); });
}

/// Takes snapshots until told to stop and records the first inconsistency it sees.
class SnapshotReader {
public:
    explicit SnapshotReader(const SolverThread& thread)
        : worker_([this, &thread](std::stop_token stop) { readUntil(stop, thread); }) {}

    void stop() {
        worker_.request_stop();
        worker_.join();
    }
    [[nodiscard]] const std::string& firstProblem() const { return problem_; }  // after stop()
    [[nodiscard]] std::size_t snapshotsRead() const { return reads_; }           // after stop()
    [[nodiscard]] std::size_t distinctMeshes() const { return meshes_.size(); }  // after stop()

private:
    void readUntil(const std::stop_token& stop, const SolverThread& thread) {
        std::uint64_t lastGeneration = 0, lastMeshGeneration = 0;
        while (!stop.stop_requested() && problem_.empty()) {
            const std::shared_ptr<const Snapshot> s = thread.snapshot();
            ++reads_;
            std::ostringstream why;
            if (s->generation < lastGeneration) why << "generation went back from " << lastGeneration << " to " << s->generation;
            if (s->meshGeneration < lastMeshGeneration)
                why << "mesh generation went back from " << lastMeshGeneration << " to " << s->meshGeneration;
            const std::size_t patches = s->mesh ? s->mesh->size() : 0;
            if (!s->radiosity.empty() && s->radiosity.size() != patches)
                why << "radiosity has " << s->radiosity.size() << " values for " << patches << " patches";
            if (!allFinite(s->radiosity)) why << "radiosity is not finite";
            if (s->mesh && (!s->scene || s->mesh->surfaceFirstPatch.size() != s->scene->surfaces.size() + 1))
                why << "mesh and scene disagree on the surface count";
            // One mesh per mesh generation: the mesh pointer changes exactly when the generation does.
            const auto [known, inserted] = meshes_.emplace(s->meshGeneration, s->mesh);
            if (!inserted && known->second != s->mesh) why << "mesh generation " << s->meshGeneration << " has two meshes";
            lastGeneration = s->generation;
            lastMeshGeneration = s->meshGeneration;
            problem_ = why.str();
        }
    }

    std::string problem_;
    std::size_t reads_ = 0;
    std::map<std::uint64_t, std::shared_ptr<const PatchMesh>> meshes_;  // kept alive: no pointer reuse
    std::jthread worker_;  // last: starts after the members it writes exist
};

struct StormResult {
    std::shared_ptr<const Snapshot> final;
    std::string readerProblem;
    std::size_t snapshotsRead = 0;
    std::size_t meshesSeen = 0;
    SolverMethod finalMethod = SolverMethod::Jacobi;
};

StormResult runStorm(std::uint64_t seed, int commands) {
    std::mt19937_64 random(seed);
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };

    auto scene = std::make_shared<const Scene>(makeCornellBox());
    std::size_t light = 0;
    for (std::size_t s = 0; s < scene->surfaces.size(); ++s)
        if (scene->materials[scene->surfaces[s].material].exitance.value().x > 0) light = s;

    SolverThread thread(cheapOptions());
    SnapshotReader reader(thread);
    thread.send(command::LoadScene{scene, MeshingOptions{kPatchAreas[0], 100'000}});
    for (int c = 0; c < commands; ++c) {
        const std::size_t kind = pick(100);
        if (kind < 20) {
            thread.send(command::Step{1 + pick(3)});
        } else if (kind < 32) {
            thread.send(command::Run{});
        } else if (kind < 44) {
            thread.send(command::Pause{});
        } else if (kind < 68) {
            // Mostly valid materials; now and then a surface that does not exist (must become an error).
            const std::size_t surface = pick(20) == 0 ? scene->surfaces.size() + pick(3) : pick(scene->surfaces.size());
            const Rgb reflectance(uniform(0, 0.8), uniform(0, 0.8), uniform(0, 0.8));
            const Rgb exitance = surface == light ? Rgb(uniform(1, 20), uniform(1, 20), uniform(1, 20)) : Rgb(0.0);
            thread.send(command::SetMaterial{surface, reflectance, ExitanceRgb(exitance)});
        } else if (kind < 74) {
            thread.send(command::SetMethod{kMethods[pick(std::size(kMethods))]});
        } else if (kind < 78) {
            thread.send(command::Remesh{MeshingOptions{kPatchAreas[pick(std::size(kPatchAreas))], 100'000}});
        } else if (kind < 88) {
            thread.send(command::Reset{});
        } else {
            // Now and then an invalid tolerance (must become an error, not a stuck solver).
            thread.send(command::SetTolerance{pick(10) == 0 ? 0.0 : kTolerances[pick(std::size(kTolerances))]});
        }
        // Bursts, then short gaps, so the worker is caught both mid-build and mid-solve.
        if (pick(16) == 0) std::this_thread::sleep_for(std::chrono::microseconds(pick(1500)));
    }

    // The final settings. Hierarchical refinement depends on the radiosity it has seen, so its links
    // after a storm differ from a fresh solve's by design: those methods are rebuilt (switch away
    // and back) before the comparison. The gathering and shooting solvers keep the state the storm
    // left them, so material edits on a live solver are what the comparison checks.
    StormResult result;
    result.finalMethod = kMethods[pick(std::size(kMethods))];
    if (result.finalMethod == SolverMethod::Hierarchical || result.finalMethod == SolverMethod::Importance)
        thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.send(command::SetMethod{result.finalMethod});
    thread.send(command::SetTolerance{kFinalTolerance});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    reader.stop();
    result.final = thread.snapshot();
    result.readerProblem = reader.firstProblem();
    result.snapshotsRead = reader.snapshotsRead();
    result.meshesSeen = reader.distinctMeshes();
    return result;
}

/// sum_i A_i |a_i - b_i| per band, W.
Rgb areaWeightedDifference(const PatchMesh& mesh, const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    Rgb sum(0.0);
    for (std::size_t i = 0; i < mesh.size(); ++i) sum += mesh.patches[i].area * glm::abs(a[i] - b[i]);
    return sum;
}

void checkStorm(std::uint64_t seed, int commands) {
    // The storm runs on its own thread so a deadlock fails the test instead of hanging the run.
    auto storm = std::async(std::launch::async, [=] { return runStorm(seed, commands); });
    constexpr auto kWatchdog = std::chrono::seconds(240);
    if (storm.wait_for(kWatchdog) != std::future_status::ready) {
        // Leak the future on purpose: destroying it would join the deadlocked thread and hang.
        new std::future<StormResult>(std::move(storm));
        FAIL("seed " << seed << ": no result after " << kWatchdog.count() << " s: the solver thread or the test deadlocked");
    }
    const StormResult result = storm.get();
    INFO("seed " << seed << ", final method " << methodName(result.finalMethod));
    CHECK_MESSAGE(result.readerProblem.empty(), result.readerProblem);
    CHECK(result.snapshotsRead > 0);
    MESSAGE(result.snapshotsRead << " snapshots read, " << result.meshesSeen << " mesh generations");

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

} // namespace

TEST_SUITE("stress") {

TEST_CASE("thousands of random commands: every snapshot consistent, the end equals a fresh solve") {
    // Three seeds end in a gathering, a shooting and a rebuilt hierarchical solver (final methods
    // Gauss-Seidel, progressive, hierarchical); each storm is reproducible from its seed.
    for (const std::uint64_t seed : {1u, 2u, 3u}) checkStorm(seed, 2000);
}

} // TEST_SUITE
