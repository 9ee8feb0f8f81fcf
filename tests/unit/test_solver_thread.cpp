// ctest-labels: threads
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <algorithm>
#include <array>
#include <set>
#include <cmath>
#include <cerrno>
#include <cstdlib>
#include <string>
#include <thread>

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "app/panels/MaterialsPanel.h"
#include "app/solver/LiveSolve.h"
#include "app/solver/SolverThread.h"
#include "app/solver/ThreadPriority.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/ParallelFor.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// A solver whose iterates are known in closed form: every patch follows B_{k+1} = E + rho B_k
/// from B_0 = E, so after k steps B = E (1 - rho^(k+1)) / (1 - rho) (a furnace).
class FurnaceLikeSolver final : public Solver {
public:
    FurnaceLikeSolver(SolverMethod method, std::size_t patches, double rho, double e)
        : method_(method), rho_(rho), e_(e), b_(patches, Rgb(e)) {}
    [[nodiscard]] SolverMethod method() const override { return method_; }
    IterationStats step() override {
        for (Rgb& b : b_) b = Rgb(e_) + rho_ * b;
        stats_.iteration += 1;
        stats_.residual = std::pow(rho_, static_cast<double>(stats_.iteration + 1));
        return stats_;
    }
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return b_; }
    void setMaterial(std::size_t, const Rgb& reflectance, const ExitanceRgb& exitance) override {
        rho_ = reflectance.x;
        e_ = exitance.value().x;
    }
    void reset() override {
        stats_ = {};
        for (Rgb& b : b_) b = Rgb(e_);
    }
    [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }

private:
    SolverMethod method_;
    double rho_, e_;
    std::vector<Rgb> b_;
    IterationStats stats_;
};

std::shared_ptr<const Scene> sharedUnitPlate() {
    auto scene = std::make_shared<Scene>();
    scene->name = "plate";
    scene->materials.push_back({"grey", Rgb(0.5), ExitanceRgb(Rgb(1.0))});
    Face face;
    face.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    face.updateGeometry();
    scene->surfaces.push_back({"plate", 0, {face}, "test"});
    return scene;
}

SolverFactory furnaceFactory(double rho, double e) {
    return [rho, e](SolverMethod method, const Scene&, const PatchMesh& mesh, const SolverOptions&, Progress*) {
        return std::make_unique<FurnaceLikeSolver>(method, mesh.size(), rho, e);
    };
}

} // namespace

TEST_SUITE("solver thread") {

TEST_CASE("the worker yields to the display: a modest nice value by default, the nice value or SCHED_IDLE RADIANT_SOLVER_NICE asks for") {
    // The factory runs on the worker thread: it reads that thread's own policy and nice value.
    struct Seen {
        std::atomic<int> policy{-1};
        std::atomic<int> nice{-100};
    };
    const auto observe = [](SolverThread& solver, Seen& seen) {
        solver.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{1.0}});
        solver.waitUntilIdle();
        CHECK(seen.policy.load() >= 0);
    };
    const auto recordingFactory = [](Seen& seen) -> SolverFactory {
        return [&seen](SolverMethod method, const Scene&, const PatchMesh& mesh, const SolverOptions&, Progress*) {
            seen.policy = sched_getscheduler(0);
            errno = 0;
            seen.nice = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
            return std::make_unique<FurnaceLikeSolver>(method, mesh.size(), 0.5, 1.0);
        };
    };
    const char* asked = std::getenv("RADIANT_SOLVER_NICE");
    const std::string saved = asked ? asked : "";
    {
        unsetenv("RADIANT_SOLVER_NICE");
        Seen seen;
        SolverThread solver({}, recordingFactory(seen));
        observe(solver, seen);
        CHECK(seen.policy.load() == SCHED_OTHER);
        CHECK(seen.nice.load() == kBackgroundNice);
    }
    {
        setenv("RADIANT_SOLVER_NICE", "idle", 1);
        Seen seen;
        SolverThread solver({}, recordingFactory(seen));
        observe(solver, seen);
        CHECK(seen.policy.load() == SCHED_IDLE);
    }
    {
        setenv("RADIANT_SOLVER_NICE", "7", 1);
        Seen seen;
        SolverThread solver({}, recordingFactory(seen));
        observe(solver, seen);
        CHECK(seen.policy.load() == SCHED_OTHER);
        CHECK(seen.nice.load() == 7);
    }
    if (asked) setenv("RADIANT_SOLVER_NICE", saved.c_str(), 1); else unsetenv("RADIANT_SOLVER_NICE");
}

TEST_CASE("steps advance exactly as many iterations as asked, and the snapshot follows") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::Step{3});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    REQUIRE(snapshot->mesh);
    CHECK(snapshot->error.empty());
    CHECK(snapshot->stats.iteration == 3);
    CHECK(snapshot->history.size() == 3);
    REQUIRE(snapshot->radiosity.size() == snapshot->mesh->size());
    const double expected = (1 - std::pow(0.5, 4)) / (1 - 0.5);
    CHECK(snapshot->radiosity.front().x == doctest::Approx(expected).scale(0));
    CHECK_FALSE(snapshot->running);
}

TEST_CASE("run stops by itself once the residual is under the tolerance") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetTolerance{1e-3});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    // residual 0.5^(k+1) < 1e-3 first at k = 9.
    CHECK(snapshot->stats.iteration == 9);
    CHECK(snapshot->stats.residual < 1e-3);
    CHECK_FALSE(snapshot->running);
}

TEST_CASE("the snapshot says whether its last step was taken by hand, so a converged solve shows no shooter") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetTolerance{1e-3});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    CHECK_FALSE(thread.snapshot()->running);
    CHECK_FALSE(thread.snapshot()->lastStepByHand);  // ran to convergence by itself
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->lastStepByHand);  // N pressed: the step's shooter is the lesson
    thread.send(command::Reset{});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    CHECK_FALSE(thread.snapshot()->lastStepByHand);
}

TEST_CASE("Reset then Run, or stepping one shot at a time, repeats the lab's first progressive solve exactly") {
    // Progressive refinement's shots draw their rays from seeds; Reset must restart those too. It did
    // not: on the lab's Cornell box a probe on the short block read -0.1% off the path tracer (green)
    // after the first solve, which `radiant solve` repeats, and -1.3% after R and Space. Each Step is
    // one shot, as each step of a run is, so N pressed to the same count must land on the same answer.
    auto box = std::make_shared<const Scene>(loadScene("cornell-box").scene);
    SolverThread thread;
    thread.send(command::LoadScene{box, MeshingOptions{0.004}});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    const auto first = thread.snapshot();
    REQUIRE(first->error.empty());
    REQUIRE(first->method == SolverMethod::Progressive);
    REQUIRE(first->stats.residual < first->tolerance);
    const std::size_t shots = first->stats.iteration;

    thread.send(command::Reset{});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    const auto again = thread.snapshot();
    CHECK(again->stats.iteration == shots);
    CHECK(again->radiosity == first->radiosity);

    thread.send(command::Reset{});
    for (std::size_t k = 0; k < shots; ++k) thread.send(command::Step{1});
    thread.waitUntilIdle();
    const auto stepped = thread.snapshot();
    CHECK(stepped->stats.iteration == shots);
    CHECK(stepped->radiosity == first->radiosity);
}

TEST_CASE("a material edit reaches the solver and the published scene, and reset starts over") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetMaterial{0, Rgb(0.25), ExitanceRgb(Rgb(2.0))});
    thread.send(command::Reset{});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    const Material& m = snapshot->scene->materials[snapshot->scene->surfaces[0].material];
    CHECK(m.reflectance.x == doctest::Approx(0.25).scale(0));
    CHECK(m.exitance.value().x == doctest::Approx(2.0).scale(0));
    CHECK(snapshot->stats.iteration == 2);
    CHECK(snapshot->radiosity.front().x == doctest::Approx(2.0 * (1 - std::pow(0.25, 3)) / 0.75).scale(0));
}

TEST_CASE("a material edit keeps a paused solve paused until the next step, and re-solves a converged one") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    LiveSolve live(thread);
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetTolerance{1e-3});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    live.refresh();
    CHECK(MaterialsPanel::submit(live, 0, Rgb(0.25), Rgb(2.0)).empty());
    thread.waitUntilIdle();
    live.refresh();
    CHECK(live.snapshot().stats.iteration == 2);  // still where the teacher left it
    CHECK_FALSE(live.snapshot().running);
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    live.refresh();
    // B_2 = (1 - 0.5^3) / 0.5 = 1.75 with the old material; one step with the new: 2 + 0.25 B_2.
    CHECK(live.snapshot().stats.iteration == 3);
    CHECK(live.snapshot().radiosity.front().x == doctest::Approx(2.0 + 0.25 * 1.75).scale(0));

    thread.send(command::Run{});
    thread.waitUntilIdle();
    live.refresh();
    const std::size_t converged = live.snapshot().stats.iteration;
    REQUIRE(live.snapshot().stats.residual < 1e-3);
    CHECK(MaterialsPanel::submit(live, 0, Rgb(0.5), Rgb(1.0)).empty());
    thread.waitUntilIdle();
    live.refresh();
    CHECK(live.snapshot().stats.iteration > converged);  // solved again, without being asked to
    CHECK_FALSE(live.snapshot().running);
}

TEST_CASE("a new mesh or grouping from the Scene panel solves on when the solve ran or had converged, and waits when it was stepped") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    LiveSolve live(thread);
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetTolerance{1e-3});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    live.refresh();
    REQUIRE(live.snapshot().stats.residual < 1e-3);
    REQUIRE(live.resumesAfterChange());
    live.sendAndResume(command::Remesh{MeshingOptions{0.0625, 1000}});
    thread.waitUntilIdle();
    live.refresh();
    CHECK(live.snapshot().mesh->size() == 16);
    // Converged again on the new mesh without a click: B = E / (1 - rho) = 2 within the tolerance.
    CHECK(live.snapshot().stats.residual < 1e-3);
    CHECK(live.snapshot().radiosity.front().x == doctest::Approx(2.0).epsilon(2e-3).scale(0));

    live.sendAndResume(command::SetGrouping{GroupingMode::On});
    thread.waitUntilIdle();
    live.refresh();
    CHECK(live.snapshot().stats.iteration > 0);
    CHECK(live.snapshot().stats.residual < 1e-3);

    thread.send(command::Reset{});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    live.refresh();
    REQUIRE_FALSE(live.resumesAfterChange());  // stepped once, not converged: the teacher is stepping
    live.sendAndResume(command::Remesh{MeshingOptions{0.25, 1000}});
    thread.waitUntilIdle();
    live.refresh();
    CHECK(live.snapshot().mesh->size() == 4);
    CHECK(live.snapshot().stats.iteration == 0);
    CHECK_FALSE(live.snapshot().running);
}

TEST_CASE("the lab's patch groups: each mesh grouped at its area, the default chosen by the groups, solved as the command line does") {
    auto scene = std::make_shared<const Scene>(
        loadScene(std::string(RADIANT_TEST_DATA_DIR) + "/grouping/sphere_room.gltf").scene);
    SolverThread thread;
    thread.send(command::LoadScene{scene, MeshingOptions{1.0}});
    thread.send(command::SetGrouping{GroupingMode::On});
    thread.send(command::Run{});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    REQUIRE(snapshot->groups);
    REQUIRE(snapshot->mesh);
    CHECK(snapshot->mesh->size() == 567);
    CHECK(snapshot->groups->size() == 63);  // as `radiant solve --group-patches --max-patch-area 1`
    CHECK(snapshot->method == SolverMethod::Progressive);
    INFO(snapshot->methodReason);
    CHECK(snapshot->methodReason.find("567 patches in 63 groups") != std::string::npos);
    CHECK(snapshot->stats.residual < snapshot->tolerance);
    REQUIRE(snapshot->radiosity.size() == snapshot->mesh->size());
    for (std::size_t g = 0; g < snapshot->groups->size(); ++g) {
        const auto patches = snapshot->groups->patchesOf(g);
        for (const std::uint32_t p : patches) CHECK(snapshot->radiosity[p] == snapshot->radiosity[patches[0]]);
    }

    thread.send(command::Remesh{MeshingOptions{0.2}});  // the new mesh is grouped at its own area
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    REQUIRE(snapshot->groups);
    CHECK(snapshot->groups->groupOf.size() == snapshot->mesh->size());
    CHECK(snapshot->groups->size() == 312);

    thread.send(command::SetGrouping{GroupingMode::Off});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK_FALSE(snapshot->groups);
    CHECK(snapshot->methodReason.find("810 patches: progressive refinement") != std::string::npos);

    // A picked method that takes no groups solves the patches and says so.
    thread.send(command::SetMethod{SolverMethod::Hierarchical});
    thread.send(command::SetGrouping{GroupingMode::On});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK_FALSE(snapshot->groups);
    CHECK(snapshot->methodTakesNoGroups);
    CHECK(snapshot->groupingReason.find("hierarchical refines its own elements and takes no groups") != std::string::npos);
}

TEST_CASE("switching between Jacobi and Gauss-Seidel on the same mesh reuses the form factors, and both reach the furnace's E / (1 - rho)") {
    // The lecture's comparison (and a lesson replayed by Page Up) recomputed the same matrix at
    // every switch. The factory runs only for matrices actually computed.
    std::atomic<int> computed{0};
    const SolverFactory counting = [&computed](SolverMethod method, const Scene& scene, const PatchMesh& mesh, const SolverOptions& o,
                                               Progress* progress) {
        ++computed;
        return makeSolver(method, scene, mesh, o, progress);
    };
    auto furnace = std::make_shared<const Scene>(loadScene("furnace").scene);
    SolverThread thread({}, counting);
    thread.send(command::LoadScene{furnace, MeshingOptions{0.1}});
    const auto converged = [&](SolverMethod method) {
        thread.send(command::SetMethod{method});
        thread.send(command::Step{60});
        thread.waitUntilIdle();
        const auto snapshot = thread.snapshot();
        REQUIRE(snapshot->error.empty());
        REQUIRE(snapshot->mesh);
        REQUIRE(snapshot->radiosity.size() == snapshot->mesh->size());
        CHECK(snapshot->method == method);
        double worst = 0;
        for (std::size_t i = 0; i < snapshot->mesh->size(); ++i) {
            const Material& m = furnace->materials[furnace->surfaces[snapshot->mesh->patches[i].surface].material];
            for (int band = 0; band < 3; ++band) {
                const double exact = m.exitance.value()[band] / (1 - m.reflectance[band]);
                worst = std::max(worst, std::abs(snapshot->radiosity[i][band] / exact - 1));
            }
        }
        return worst;
    };
    CHECK(converged(SolverMethod::Jacobi) < 2e-3);
    const int first = computed.load();  // the opening default method's solver, then Jacobi's
    CHECK(converged(SolverMethod::GaussSeidel) < 2e-3);
    CHECK(converged(SolverMethod::Jacobi) < 2e-3);
    CHECK(computed.load() == first);  // one matrix for the three solvers
    // Another method between them keeps the matrix.
    thread.send(command::SetMethod{SolverMethod::Progressive});
    thread.send(command::Step{1});
    CHECK(converged(SolverMethod::GaussSeidel) < 2e-3);
    CHECK(computed.load() == first + 1);  // the progressive solver, none for Gauss-Seidel
    // A new mesh computes the picked method's matrix once, which the switch back to Jacobi reuses.
    thread.send(command::Remesh{MeshingOptions{0.05}});
    CHECK(converged(SolverMethod::Jacobi) < 2e-3);
    CHECK(computed.load() == first + 2);
}

TEST_CASE("hierarchical solvers publish their links as segments between the elements they join, others none") {
    auto plates = std::make_shared<const Scene>(loadScene("parallel-plates").scene);
    SolverThread thread;
    thread.send(command::LoadScene{plates, MeshingOptions{0.05}});
    thread.send(command::SetMethod{SolverMethod::Hierarchical});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    REQUIRE(snapshot->linkSegments);
    CHECK(snapshot->linkSegments->size() == 2 * snapshot->stats.links);
    CHECK(snapshot->stats.links > 1);  // refined beyond the one link between the two roots
    CHECK_FALSE(snapshot->importance);
    // The plates are the unit squares y = 0 and y = 1 facing each other: every link joins one to the other.
    for (std::size_t i = 0; i + 1 < snapshot->linkSegments->size(); i += 2) {
        const glm::vec3 a = (*snapshot->linkSegments)[i], b = (*snapshot->linkSegments)[i + 1];
        CAPTURE(i);
        CHECK(std::abs(a.y - b.y) == doctest::Approx(1.0).scale(0));
        for (const glm::vec3& end : {a, b}) {
            CHECK((end.x > 0 && end.x < 1 && end.z > 0 && end.z < 1));
            CHECK((std::abs(end.y) < 1e-6 || std::abs(end.y - 1) < 1e-6));
        }
    }

    thread.send(command::SetMethod{SolverMethod::GaussSeidel});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK_FALSE(snapshot->linkSegments);
    CHECK_FALSE(snapshot->importance);
}

TEST_CASE("a focused point gets the links of its element and each ancestor, all from elsewhere, other methods none") {
    SolverThread solver;
    auto box = std::make_shared<const Scene>(loadScene("cornell-box").scene);
    solver.send(command::LoadScene{box, MeshingOptions{0.01}});
    solver.send(command::SetMethod{SolverMethod::Hierarchical});
    solver.send(command::Step{6});
    solver.waitUntilIdle();
    const std::shared_ptr<const Snapshot> unfocused = solver.snapshot();
    REQUIRE(unfocused->linkSegments);
    CHECK_FALSE(unfocused->focusLinkSegments);

    // A floor point (the floor is y = 0), found as the probe finds it: by a ray.
    const RayCaster rays(*box);
    const std::optional<RayHit> hit = rays.intersect({0.45, 0.3, 0.1}, {0, -1, 0});
    REQUIRE(hit);
    REQUIRE(hit->point.y == doctest::Approx(0.0).epsilon(1e-6));
    solver.send(command::FocusPoint{command::FocusedPoint{hit->surface, hit->face, hit->point, unfocused->meshGeneration}});
    solver.waitUntilIdle();
    const std::shared_ptr<const Snapshot> focused = solver.snapshot();
    REQUIRE(focused->focusLinkSegments);
    const std::vector<glm::vec3>& ends = *focused->focusLinkSegments;
    CHECK(ends.size() % 2 == 0);
    std::set<std::array<float, 3>> sources;  // of every link that a floor element receives
    for (std::size_t i = 0; i + 1 < focused->linkSegments->size(); i += 2) {
        const glm::vec3 receiver = (*focused->linkSegments)[i], source = (*focused->linkSegments)[i + 1];
        if (std::abs(receiver.y) < 1e-5f) sources.insert({source.x, source.y, source.z});
    }
    for (std::size_t i = 0; i + 1 < ends.size(); i += 2) {
        const glm::vec3 from = ends[i], source = ends[i + 1];
        CAPTURE(i);
        // From the point itself, to something it sees that a floor element gathers from.
        CHECK(from == glm::vec3(hit->point));
        CHECK(source.y > 1e-3f);
        CHECK(sources.count({source.x, source.y, source.z}) == 1);
    }
    // The chain from the deepest element under the point to its root: a floor point by the blocks
    // gathers over links at more than one level of it, each holding at least one link.
    CHECK(focused->focusLevels >= 2);
    CHECK(ends.size() / 2 >= focused->focusLevels);
    const std::size_t focusedLinks = ends.size() / 2;
    CHECK(focusedLinks < focused->linkSegments->size() / 2);  // a few of the box's links, not all

    solver.send(command::FocusPoint{});
    solver.waitUntilIdle();
    CHECK_FALSE(solver.snapshot()->focusLinkSegments);
    // A point picked on an older mesh is ignored.
    solver.send(command::FocusPoint{command::FocusedPoint{hit->surface, hit->face, hit->point, unfocused->meshGeneration + 1}});
    solver.waitUntilIdle();
    CHECK_FALSE(solver.snapshot()->focusLinkSegments);
    solver.send(command::FocusPoint{command::FocusedPoint{hit->surface, hit->face, hit->point, unfocused->meshGeneration}});
    solver.send(command::SetMethod{SolverMethod::GaussSeidel});
    solver.waitUntilIdle();
    CHECK_FALSE(solver.snapshot()->focusLinkSegments);
}

TEST_CASE("the importance method publishes each patch's importance") {
    auto cornell = std::make_shared<const Scene>(loadScene("cornell-box").scene);
    SolverThread thread;
    thread.send(command::LoadScene{cornell, MeshingOptions{0.05}});
    thread.send(command::SetMethod{SolverMethod::Importance});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    REQUIRE(snapshot->importance);
    REQUIRE(snapshot->mesh);
    CHECK(snapshot->importance->size() == snapshot->mesh->size());
    double largest = 0;
    for (const double y : *snapshot->importance) {
        CHECK(y >= 0);
        largest = std::max(largest, y);
    }
    CHECK(largest > 0);  // the camera sees the box
    CHECK(snapshot->linkSegments);
}

TEST_CASE("materials edits keep the solver (no new form factors), while a new method or mesh builds one") {
    std::atomic<int> factoryCalls{0};
    SolverFactory counting = [&](SolverMethod method, const Scene&, const PatchMesh& mesh, const SolverOptions&,
                                 Progress*) -> std::unique_ptr<Solver> {
        ++factoryCalls;
        return std::make_unique<FurnaceLikeSolver>(method, mesh.size(), 0.5, 1.0);
    };
    SolverThread thread({}, counting);
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->solverBuilds == 1);
    CHECK(thread.snapshot()->meshing.maxPatchArea == 0.25);
    for (int i = 0; i < 3; ++i) thread.send(command::SetMaterial{0, Rgb(0.1 * i), ExitanceRgb(Rgb(1.0))});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->solverBuilds == 1);
    CHECK(factoryCalls.load() == 1);
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->solverBuilds == 2);
    thread.send(command::Remesh{MeshingOptions{0.0625, 1000}});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->solverBuilds == 3);
    CHECK(thread.snapshot()->mesh->size() == 16);
    CHECK(factoryCalls.load() == 3);
}

TEST_CASE("a new method cancels a form-factor computation in progress") {
    std::atomic<int> builds{0};
    std::atomic<int> cancelled{0};
    SolverFactory slow = [&](SolverMethod method, const Scene&, const PatchMesh& mesh, const SolverOptions&,
                             Progress* progress) -> std::unique_ptr<Solver> {
        ++builds;
        if (method == SolverMethod::Jacobi) {
            // Stands in for a long form-factor matrix: only cancellation ends it.
            for (;;) {
                try {
                    progress->checkCancelled();
                } catch (const Cancelled&) {
                    ++cancelled;
                    throw;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
        }
        return std::make_unique<FurnaceLikeSolver>(method, mesh.size(), 0.5, 1.0);
    };
    SolverThread thread({}, slow);
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    // Wait until the slow build is under way, then replace it.
    for (int i = 0; i < 5000 && thread.activity() != SolverActivity::FormFactors; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    REQUIRE(thread.activity() == SolverActivity::FormFactors);
    thread.send(command::SetMethod{SolverMethod::GaussSeidel});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    CHECK(cancelled.load() == 1);
    const auto snapshot = thread.snapshot();
    CHECK(snapshot->method == SolverMethod::GaussSeidel);
    CHECK(snapshot->stats.iteration == 1);
}

TEST_CASE("a new method stops a long step at once: the step's parallel loop is cancelled between chunks") {
    // Stands in for a hierarchical sweep over 60k patches (over 35 s before steps were cancellable):
    // a Jacobi step whose parallel loop would run kChunks chunks of 1 ms.
    constexpr std::size_t kChunks = 100000;
    std::atomic<std::size_t> chunksRun{0};
    class LongStepSolver final : public Solver {
    public:
        LongStepSolver(std::size_t patches, std::atomic<std::size_t>& chunks) : b_(patches, Rgb(1.0)), chunks_(chunks) {}
        [[nodiscard]] SolverMethod method() const override { return SolverMethod::Jacobi; }
        IterationStats step() override {
            parallelFor(kChunks, 1, [&](std::size_t, std::size_t) {
                chunks_.fetch_add(1);
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            });
            stats_.iteration += 1;
            return stats_;
        }
        [[nodiscard]] const std::vector<Rgb>& solution() const override { return b_; }
        void setMaterial(std::size_t, const Rgb&, const ExitanceRgb&) override {}
        void reset() override { stats_ = {}; }
        [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }

    private:
        std::vector<Rgb> b_;
        std::atomic<std::size_t>& chunks_;
        IterationStats stats_;
    };
    SolverFactory factory = [&](SolverMethod method, const Scene&, const PatchMesh& mesh, const SolverOptions&,
                                Progress*) -> std::unique_ptr<Solver> {
        if (method == SolverMethod::Jacobi) return std::make_unique<LongStepSolver>(mesh.size(), chunksRun);
        return std::make_unique<FurnaceLikeSolver>(method, mesh.size(), 0.5, 1.0);
    };
    SolverThread thread({}, factory);
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::Run{});
    // Progress, not wall time: wait until the long step has begun its chunks.
    while (chunksRun.load() == 0) std::this_thread::yield();
    thread.send(command::SetMethod{SolverMethod::GaussSeidel});
    thread.send(command::Pause{});
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    CHECK(chunksRun.load() < kChunks / 10);
    const auto snapshot = thread.snapshot();
    CHECK(snapshot->method == SolverMethod::GaussSeidel);
    CHECK(snapshot->stats.iteration == 1);
    CHECK(snapshot->error.empty());
}

TEST_CASE("the history a snapshot carries is every step in order while the worker steps, and shares its full chunks") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    constexpr std::size_t kSteps = 2 * SolveHistory::kChunkSize + 500;
    thread.send(command::Step{kSteps});
    // Read every snapshot published during the steps on this thread, as the panels do.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    std::uint64_t seen = 0;
    std::shared_ptr<const Snapshot> s = thread.snapshot();
    while (s->stats.iteration < kSteps || s->running) {
        REQUIRE(std::chrono::steady_clock::now() < deadline);
        if (s->generation != seen) {
            seen = s->generation;
            REQUIRE(s->history.size() == s->stats.iteration);
            bool inOrder = true;
            for (std::size_t i = 0; i < s->history.size(); ++i) inOrder = inOrder && s->history[i].iteration == i + 1;
            REQUIRE(inOrder);
        }
        std::this_thread::yield();
        s = thread.snapshot();
    }
    thread.waitUntilIdle();
    const auto first = thread.snapshot();
    REQUIRE(first->history.size() == kSteps);
    CHECK(first->history.back().iteration == kSteps);
    thread.send(command::Step{SolveHistory::kChunkSize});  // freezes a third chunk
    thread.waitUntilIdle();
    const auto second = thread.snapshot();
    REQUIRE(second->history.size() == kSteps + SolveHistory::kChunkSize);
    REQUIRE(first->history.frozenChunks().size() == 2);
    REQUIRE(second->history.frozenChunks().size() == 3);
    for (std::size_t c = 0; c < 2; ++c)
        CHECK(first->history.frozenChunks()[c].get() == second->history.frozenChunks()[c].get());
    CHECK(first->history.size() == kSteps);  // the earlier snapshot did not see the later steps
    thread.send(command::Reset{});
    thread.waitUntilIdle();
    CHECK(thread.snapshot()->history.empty());
    CHECK(thread.snapshot()->history.frozenChunks().empty());
}

TEST_CASE("generations only grow, and the reader never waits for a step") {
    SolverThread thread({}, furnaceFactory(0.9, 1.0));
    thread.send(command::LoadScene{sharedUnitPlate(), MeshingOptions{0.25, 1000}});
    thread.send(command::SetTolerance{1e-12});
    thread.send(command::Run{});
    std::uint64_t last = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto s = thread.snapshot();
        CHECK(s->generation >= last);
        last = s->generation;
        if (s->mesh) CHECK(s->radiosity.size() == s->mesh->size());
    }
    thread.send(command::Pause{});
    thread.waitUntilIdle();
    CHECK_FALSE(thread.snapshot()->running);
}

TEST_CASE("the convergence record overlays methods, cuts a segment at a material edit, and Reset materials restores the scene as loaded") {
    SolverThread thread({}, furnaceFactory(0.5, 1.0));
    const std::shared_ptr<const Scene> loaded = sharedUnitPlate();
    thread.send(command::LoadScene{loaded, MeshingOptions{0.25, 1000}});
    thread.send(command::SetMethod{SolverMethod::GaussSeidel});
    // Commands go before pending steps: each step request is waited for before the next command.
    thread.send(command::Step{3});
    thread.waitUntilIdle();
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    thread.send(command::SetMaterial{0, Rgb(0.25), ExitanceRgb(Rgb(2.0))});
    thread.send(command::Step{4});
    thread.waitUntilIdle();
    auto s = thread.snapshot();
    std::vector<SegmentView> segments = s->convergence.segments(s->history);
    REQUIRE(segments.size() == 3);
    CHECK(segments[0].info->method == SolverMethod::GaussSeidel);
    CHECK(segments[0].steps->size() == 3);
    CHECK(segments[1].info->method == SolverMethod::Jacobi);
    CHECK(segments[1].steps->size() == 2);
    CHECK(segments[2].info->label == "Jacobi, edit 1: plate");
    CHECK(segments[2].steps->size() == 4);
    CHECK(s->history.size() == 4);  // the segment being solved
    CHECK(s->scene->materials[s->scene->surfaces[0].material].reflectance.x == 0.25);

    thread.send(command::ResetMaterials{});
    thread.waitUntilIdle();
    s = thread.snapshot();
    CHECK(s->scene == loaded);
    CHECK(s->stats.iteration == 0);  // restarted from B = E
    segments = s->convergence.segments(s->history);
    REQUIRE(segments.size() == 1);  // Jacobi's runs went with the restart; Gauss-Seidel's stays
    CHECK(segments[0].info->method == SolverMethod::GaussSeidel);
    CHECK(s->convergence.current().label == "Jacobi");

    // The solver has the loaded material again: one step from B = E gives E (1 + rho) = 1.5.
    thread.send(command::Step{1});
    thread.waitUntilIdle();
    s = thread.snapshot();
    REQUIRE_FALSE(s->radiosity.empty());
    CHECK(s->radiosity.front().x == doctest::Approx(1.5).scale(0));
}

} // TEST_SUITE
