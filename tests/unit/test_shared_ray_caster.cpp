// ctest-labels: threads
// One ray caster (one Embree BVH) per scene the lab loads: the solver thread builds it when it takes
// LoadScene and every solver, snapshot and panel shares it. Counted through RayCaster::constructed(),
// so a solver that quietly built its own again would fail here.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <memory>

#include "app/cli/CommandLine.h"
#include "app/solver/SolverThread.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/SolverMethods.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// The Cornell box with a punctual light as well, so the lights' shadow rays (every method's
/// direct term) are among what must share the caster.
std::shared_ptr<const Scene> litCornellBox() {
    Scene box = loadScene("cornell-box").scene;
    PunctualLight bulb;
    bulb.name = "bulb";
    bulb.position = {0.45, 0.45, 0.12};  // above a clear stretch of floor
    bulb.intensity = IntensityRgb(Rgb(0.05));
    box.lights.push_back(bulb);
    return std::make_shared<const Scene>(std::move(box));
}

/// Sends a command, waits for it, and returns the snapshot after it with how many ray casters the
/// process built meanwhile.
std::pair<std::shared_ptr<const Snapshot>, std::uint64_t> apply(SolverThread& thread, SolverCommand command) {
    const std::uint64_t before = RayCaster::constructed();
    thread.send(std::move(command));
    thread.waitUntilIdle();
    return {thread.snapshot(), RayCaster::constructed() - before};
}

} // namespace

TEST_CASE("the lab builds one ray caster per loaded scene and shares it across materials, methods, meshes and probes") {
    SolverThread thread;
    const auto [loaded, loadBuilds] = apply(thread, command::LoadScene{litCornellBox(), MeshingOptions{0.02}});
    REQUIRE(loaded->error.empty());
    REQUIRE(loaded->rays);
    REQUIRE(loaded->mesh);
    REQUIRE(loaded->solverBuilds == 1);  // the default method's solver, built from the shared caster
    CHECK(loadBuilds == 1);
    const RayCaster* shared = loaded->rays.get();

    std::uint64_t solverBuilds = loaded->solverBuilds;
    for (const SolverMethodInfo& info : solverMethods()) {
        if (info.method == loaded->method) continue;
        CAPTURE(info.name);
        const auto [changed, builds] = apply(thread, command::SetMethod{info.method});
        REQUIRE(changed->error.empty());
        CHECK(changed->solverBuilds == ++solverBuilds);  // a new solver was built ...
        CHECK(builds == 0);                                // ... without a BVH of its own
        CHECK(changed->rays.get() == shared);
    }

    const auto [edited, editBuilds] =
        apply(thread, command::SetMaterial{0, Rgb(0.3), ExitanceRgb(Rgb(0.0)), false});
    REQUIRE(edited->error.empty());
    CHECK(edited->scene != loaded->scene);  // a new Scene object with the same geometry ...
    CHECK(editBuilds == 0);
    CHECK(edited->rays.get() == shared);    // ... keeps the caster

    const auto [remeshed, remeshBuilds] = apply(thread, command::Remesh{MeshingOptions{0.01}});
    REQUIRE(remeshed->error.empty());
    CHECK(remeshed->meshGeneration != loaded->meshGeneration);
    CHECK(remeshed->mesh->size() > loaded->mesh->size());
    CHECK(remeshBuilds == 0);  // the same faces: the same caster, for the new solver too
    CHECK(remeshed->rays.get() == shared);

    // The probe (the Probe panel's reading) casts through the snapshot's caster.
    const std::uint64_t beforeProbe = RayCaster::constructed();
    const std::optional<RayHit> floor = remeshed->rays->intersectFront({0.45, 0.3, 0.1}, {0, -1, 0});
    REQUIRE(floor);
    const Probe probe(*remeshed->scene, *remeshed->mesh, remeshed->rays.get());
    const ProbeReading reading = probe.measure(floor->point, floor->normal, remeshed->radiosity, std::nullopt);
    CHECK(reading.directIrradiance.value().y > 0);  // the bulb's shadow ray found it unblocked
    CHECK(RayCaster::constructed() == beforeProbe);

    const auto [other, otherBuilds] = apply(thread, command::LoadScene{litCornellBox(), MeshingOptions{0.02}});
    REQUIRE(other->error.empty());
    CHECK(otherBuilds == 1);  // a new scene: its own caster, once
    REQUIRE(other->rays);
    CHECK(other->rays != remeshed->rays);
}

TEST_CASE("a command builds one ray caster for its mesher (the blocks' covered pieces) and its solver") {
    const Scene box = loadScene("cornell-box").scene;
    const std::uint64_t before = RayCaster::constructed();
    const CommandSystem system = meshForCommand("gauss-seidel", box, 0.01, GroupingMode::Off);
    const bool anyCovered = std::any_of(system.mesh.patches.begin(), system.mesh.patches.end(), [](const Patch& p) { return p.covered; });
    CHECK(anyCovered);  // the mesher traced rays for the pieces under the blocks
    const auto solver = makeCommandSolver(box, system, SolverOptions{});
    solver->step();
    CHECK(RayCaster::constructed() - before == 1);
}
