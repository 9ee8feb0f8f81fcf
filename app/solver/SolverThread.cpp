#include "app/solver/SolverThread.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <tuple>
#include <type_traits>

#include "app/solver/ThreadPriority.h"
#include "radiometry/common/CancellationScope.h"
#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/solver/DefaultGrouping.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "radiometry/solver/GroupedSolver.h"
#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/HierarchicalSolver.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/WorkerPool.h"

namespace radiant::app {

std::string_view activityName(SolverActivity activity) {
    switch (activity) {
    case SolverActivity::Idle: return "idle";
    case SolverActivity::Meshing: return "meshing";
    case SolverActivity::FormFactors: return "computing form factors";
    case SolverActivity::Solving: return "solving";
    }
    return "?";
}

/// Everything the worker owns. Only the worker thread touches it.
struct SolverThread::State {
    std::shared_ptr<const Scene> scene;
    /// The one ray caster of `scene`'s geometry, built when LoadScene takes the scene and shared by
    /// the solvers, the snapshots and the panels; materials edits and re-meshing keep it (neither
    /// changes a face).
    std::shared_ptr<const RayCaster> rays;
    MeshingOptions meshing;
    std::shared_ptr<const PatchMesh> mesh;
    /// command::SetGrouping, and what chooseSystem made of it for `mesh` and `method`: the patch
    /// groups solved as the unknowns (null: the patches), why, and whether a picked method took none.
    GroupingMode grouping = GroupingMode::Auto;
    std::shared_ptr<const PatchGroups> groups;
    std::string groupingReason;
    bool methodTakesNoGroups = false;
    std::unique_ptr<Solver> solver;
    /// The scene and mesh the solver was built from, kept alive as long as it is: a solver may hold
    /// references to them, while materials edits replace `scene`.
    std::shared_ptr<const Scene> solverScene;
    std::shared_ptr<const PatchMesh> solverMesh;
    std::shared_ptr<const PatchGroups> solverGroups;
    /// The form factors of the last Jacobi or Gauss-Seidel solver of the patches of `keptMatrixMesh`:
    /// switching between the two on the same mesh reuses them (the lecture's Jacobi-against-Gauss-Seidel
    /// moment, and a lesson replayed by Page Up, recomputed the same matrix each time).
    std::shared_ptr<const FormFactorMatrix> keptMatrix;
    std::shared_ptr<const PatchMesh> keptMatrixMesh;
    SolverMethod method = kSolveDefaults.method;
    /// The user picked `method` (SetMethod) for this scene; otherwise each new mesh chooses it by its
    /// size (DefaultMethod.h) and `methodReason` says why.
    bool methodPicked = false;
    std::string methodReason;
    std::optional<View> view;  ///< the lab's camera for importance; none: the scene's home view
    bool running = false;
    std::size_t pendingSteps = 0;
    bool lastStepByHand = false;  ///< Snapshot::lastStepByHand
    double tolerance = kSolveDefaults.tolerance;
    ConvergenceRecorder history{kSolveDefaults.method};
    /// The scene as LoadScene gave it, before any material edit: what ResetMaterials restores.
    std::shared_ptr<const Scene> loadedScene;
    std::uint64_t generation = 0;
    std::uint64_t meshGeneration = 0;
    std::uint64_t solverBuilds = 0;
    std::string error;
    std::chrono::steady_clock::time_point lastPublish{};
    /// The link segments last published and what they were made from: rebuilt only when the
    /// solver, its link count or (through a command) its links may have changed.
    std::shared_ptr<const std::vector<glm::vec3>> linkSegments;
    const Solver* linkSolver = nullptr;
    std::size_t linkCount = 0;
    bool linksStale = true;
    std::optional<command::FocusedPoint> focus;
    std::shared_ptr<const std::vector<glm::vec3>> focusSegments;  ///< rebuilt with the links or the focus
    std::size_t focusLevels = 0;
    bool focusStale = true;
};

namespace {
// A shooting solver may take thousands of steps a second; the display needs at most one
// snapshot per frame, and each snapshot copies the radiosity (the history only in part).
constexpr auto kPublishInterval = std::chrono::milliseconds(12);
/// The lab's words for coarser meshing in the form-factor budget's refusal (ScenePanel's slider).
constexpr std::string_view kLabCoarserMeshing = "a larger patch area (the Scene panel's meshing slider)";

std::vector<Rgb> emittedRadiosity(const Scene& scene, const PatchMesh& mesh) {
    std::vector<Rgb> b(mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Surface& surface = scene.surfaces[mesh.patches[i].surface];
        b[i] = scene.materials[surface.material].exitance.value();
    }
    return b;
}

/// Each link as a segment from its receiver's centroid to its source's.
std::shared_ptr<const std::vector<glm::vec3>> linkSegments(const HierarchicalSolver& solver) {
    auto segments = std::make_shared<std::vector<glm::vec3>>();
    const ElementTree& tree = solver.elements();
    segments->reserve(solver.links().size() * 2);
    for (const Link& link : solver.links()) {
        segments->push_back(glm::vec3(tree.polygon(link.receiver).centroid));
        segments->push_back(glm::vec3(tree.polygon(link.source).centroid));
    }
    return segments;
}

/// The links a point gathers through: those of the deepest element containing it and of each of its
/// ancestors (push-pull hands every ancestor's gathered irradiance down to it), as segments from the
/// point to each link's source, with the number of tree levels that hold at least one of them.
std::pair<std::shared_ptr<const std::vector<glm::vec3>>, std::size_t> focusLinkSegments(
    const HierarchicalSolver& solver, const command::FocusedPoint& at) {
    const ElementTree& tree = solver.elements();
    const ElementIndex deepest = tree.locate(at.surface, at.face, at.point);
    if (deepest == kNoElement) return {nullptr, 0};
    std::vector<char> onChain(tree.size(), 0);
    for (ElementIndex e = deepest; e != kNoElement; e = tree.parent(e)) onChain[e] = 1;
    std::vector<bool> linkedAtDepth(tree.depth(deepest) + 1, false);
    auto segments = std::make_shared<std::vector<glm::vec3>>();
    for (const Link& link : solver.links()) {
        if (!onChain[link.receiver]) continue;
        // From the point itself: whatever the level, it receives that link's light (push-pull).
        segments->push_back(glm::vec3(at.point));
        segments->push_back(glm::vec3(tree.polygon(link.source).centroid));
        linkedAtDepth[tree.depth(link.receiver)] = true;
    }
    return {std::move(segments),
            static_cast<std::size_t>(std::count(linkedAtDepth.begin(), linkedAtDepth.end(), true))};
}

/// Index of the first patch whose radiosity is NaN or infinite, or npos.
std::size_t firstNonFinite(const std::vector<Rgb>& radiosity) {
    for (std::size_t i = 0; i < radiosity.size(); ++i)
        if (!std::isfinite(radiosity[i].x) || !std::isfinite(radiosity[i].y) || !std::isfinite(radiosity[i].z)) return i;
    return std::string::npos;
}
} // namespace

SolverThread::SolverThread(SolverOptions options, SolverFactory factory)
    : options_(std::move(options)), factory_(std::move(factory)) {
    if (!factory_) {
        factory_ = [](SolverMethod method, const Scene& scene, const PatchMesh& mesh, const SolverOptions& o,
                      Progress* progress) { return makeSolver(method, scene, mesh, o, progress); };
    }
    published_ = std::make_shared<const Snapshot>();
    worker_ = std::jthread([this](std::stop_token stop) { workerLoop(stop); });
}

SolverThread::~SolverThread() {
    progress_.cancelRequested.store(true);
    worker_.request_stop();
    queueChanged_.notify_all();
    // jthread joins here.
}

bool SolverThread::cancelsLongWork(const SolverCommand& command, SolverActivity activity) {
    // A new method makes form factors and the current step pointless but not the mesh; a new mesh or
    // scene makes all three. A step is stopped between chunks of its parallel loops
    // (CancellationScope), and the solver is dropped: these commands replace it anyway.
    const bool solverWork = activity == SolverActivity::FormFactors || activity == SolverActivity::Solving;
    if (std::holds_alternative<command::SetMethod>(command) || std::holds_alternative<command::SetLinkTolerance>(command) ||
        std::holds_alternative<command::SetGrouping>(command))
        return solverWork;
    if (std::holds_alternative<command::Remesh>(command) || std::holds_alternative<command::LoadScene>(command))
        return solverWork || activity == SolverActivity::Meshing;
    return false;
}

void SolverThread::send(SolverCommand command) {
    const bool cancel = cancelsLongWork(command, activity());
    {
        std::lock_guard lock(queueMutex_);
        queue_.push_back(std::move(command));
    }
    // The worker clears the request when it starts new long work, so a late request can at worst
    // cancel one build or meshing too many: a cancelled meshing re-queues itself (see apply), and a
    // cancelled build is redone when the solver is next needed.
    if (cancel) progress_.cancelRequested.store(true);
    queueChanged_.notify_all();
}

std::shared_ptr<const Snapshot> SolverThread::snapshot() const {
    std::lock_guard lock(publishedMutex_);
    return published_;
}

void SolverThread::waitUntilIdle() {
    std::unique_lock lock(queueMutex_);
    idle_.wait(lock, [&] { return queue_.empty() && !workerBusy_; });
}

SolverThread::Heartbeat SolverThread::heartbeat() const {
    return {commandsTaken_.load(std::memory_order_relaxed), generationPublished_.load(std::memory_order_relaxed),
            lastCommand_.load(std::memory_order_relaxed)};
}

void SolverThread::workerLoop(const std::stop_token& stop) {
    yieldToTheDisplay();
    // The shared pool's helpers inherit the policy of the thread that starts them: started here, they
    // yield to the display as this thread does (a pool started elsewhere first keeps its own).
    WorkerPool::shared();
    State state;
    while (!stop.stop_requested()) {
        std::optional<SolverCommand> next;
        {
            std::unique_lock lock(queueMutex_);
            const bool hasWork = state.running || state.pendingSteps > 0;
            if (queue_.empty() && !hasWork) {
                workerBusy_ = false;
                activity_.store(SolverActivity::Idle);
                idle_.notify_all();
                queueChanged_.wait(lock, stop, [&] { return !queue_.empty(); });
                if (stop.stop_requested()) break;
            }
            if (!queue_.empty()) {
                next = std::move(queue_.front());
                queue_.pop_front();
                lastCommand_.store(next->index(), std::memory_order_relaxed);
                commandsTaken_.fetch_add(1, std::memory_order_relaxed);
            } else {
                // About to step with nothing queued: a request left by a command already applied
                // must not stop this step. send() sets it after queueing, so a newer one still does.
                progress_.cancelRequested.store(false);
            }
            workerBusy_ = true;
        }
        try {
            if (next) {
                state.error.clear();
                state.linksStale = true;
                apply(state, *next);
                publish(state);
                continue;
            }
            ensureSolver(state);
            if (!state.solver) {
                state.running = false;
                state.pendingSteps = 0;
                publish(state);
                continue;
            }
            activity_.store(SolverActivity::Solving);
            const bool byHand = !state.running && state.pendingSteps > 0;
            const IterationStats stats = [&] {
                const CancellationScope cancellable(progress_);
                return state.solver->step();
            }();
            state.history.append(stats);
            state.lastStepByHand = byHand;
            if (state.pendingSteps > 0) --state.pendingSteps;
            if (state.running && stats.residual < state.tolerance) state.running = false;
            const bool settled = !state.running && state.pendingSteps == 0;
            if (settled || std::chrono::steady_clock::now() - state.lastPublish >= kPublishInterval) publish(state);
        } catch (const FormFactorBudgetError& e) {
            // The lab's own control for coarser meshing, not the command line's flag.
            state.error = e.where().str() + ": " + e.message(kLabCoarserMeshing);
            state.running = false;
            state.pendingSteps = 0;
            publish(state);
        } catch (const Cancelled&) {
            // A newer command made the work pointless; it is next in the queue.
            state.solver.reset();
            publish(state);
        } catch (const std::exception& e) {
            state.error = e.what();
            state.running = false;
            state.pendingSteps = 0;
            publish(state);
        }
    }
    std::lock_guard lock(queueMutex_);
    workerBusy_ = false;
    idle_.notify_all();
}

void SolverThread::requeueMeshingUnlessSuperseded(const MeshingOptions& meshing) {
    std::lock_guard lock(queueMutex_);
    for (const SolverCommand& queued : queue_)
        if (std::holds_alternative<command::Remesh>(queued) || std::holds_alternative<command::LoadScene>(queued))
            return;
    queue_.push_front(command::Remesh{meshing});
}

/// The unknowns and, unless the user picked one, the method for the current mesh, as `radiant solve`
/// chooses them at --max-patch-area (DefaultGrouping.h).
void SolverThread::chooseUnknowns(State& state) {
    std::optional<SolverMethod> picked;
    if (state.methodPicked) picked = state.method;
    SystemChoice choice = chooseSystem(*state.mesh, state.meshing.maxPatchArea, state.grouping, picked);
    state.groups = std::move(choice.groups);
    state.groupingReason = std::move(choice.groupingReason);
    state.methodTakesNoGroups = choice.methodTakesNoGroups;
    if (!state.methodPicked) {
        state.method = choice.method.method;
        state.methodReason = std::move(choice.method.reason);
    }
}

void SolverThread::startNewSystem(State& state) {
    chooseUnknowns(state);
    state.solver.reset();
    state.running = false;
    state.pendingSteps = 0;
    state.history.clear(state.method);
    publish(state);  // show the new mesh (emission only) while form factors compute
    ensureSolver(state);
}

void SolverThread::apply(State& state, SolverCommand& command) {
    std::visit(
        [&](auto& c) {
            using C = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<C, command::Run>) {
                state.running = true;
            } else if constexpr (std::is_same_v<C, command::Pause>) {
                state.running = false;
                state.pendingSteps = 0;
            } else if constexpr (std::is_same_v<C, command::Step>) {
                state.running = false;
                state.pendingSteps += c.count;
            } else if constexpr (std::is_same_v<C, command::Reset>) {
                state.running = false;
                state.pendingSteps = 0;
                state.history.restart(state.method);
                if (state.solver) state.solver->reset();
            } else if constexpr (std::is_same_v<C, command::FocusPoint>) {
                state.focus = c.at;
                state.focusStale = true;
            } else if constexpr (std::is_same_v<C, command::SetView>) {
                // Throws (the previous view stays) for a view with no importance: the lab shows why.
                if (state.solver && state.solver->setView(*state.solverScene, c.view)) state.running = true;
                state.view = c.view;
            } else if constexpr (std::is_same_v<C, command::SetTolerance>) {
                if (!(c.tolerance > 0)) throw RadiantError({"", "tolerance"}, "must be positive, got " + std::to_string(c.tolerance));
                state.tolerance = c.tolerance;
            } else if constexpr (std::is_same_v<C, command::SetLinkTolerance>) {
                if (!(c.linkTolerance > 0))
                    throw RadiantError({"", "link tolerance"}, "must be positive, got " + std::to_string(c.linkTolerance));
                options_.linkEpsilon = c.linkTolerance;
                if (methodInfo(state.method).traits.links) {
                    state.solver.reset();  // the links were refined to the old tolerance
                    state.history.restart(state.method);
                    ensureSolver(state);
                }
            } else if constexpr (std::is_same_v<C, command::SetMethod>) {
                state.methodPicked = true;
                state.methodReason.clear();
                if (c.method != state.method || !state.solver) {
                    if (state.solver && !state.solverGroups && state.solver->formFactorMatrix()) {
                        state.keptMatrix = state.solver->formFactorMatrix();
                        state.keptMatrixMesh = state.solverMesh;
                    }
                    state.method = c.method;
                    // Hierarchical takes no groups (it solves the patches); a picked method may
                    // group where the default would not (beyond kProgressiveMaxPatches groups).
                    if (state.mesh) chooseUnknowns(state);
                    state.solver.reset();
                    state.history.restart(c.method);  // the other methods' runs stay, to compare
                    ensureSolver(state);
                }
            } else if constexpr (std::is_same_v<C, command::SetGrouping>) {
                if (c.mode == state.grouping) return;
                state.grouping = c.mode;
                if (!state.mesh) return;  // the next mesh is grouped
                startNewSystem(state);
            } else if constexpr (std::is_same_v<C, command::SetMaterial>) {
                if (!state.scene || c.surface >= state.scene->surfaces.size())
                    throw RadiantError({"", "set material"}, "no surface " + std::to_string(c.surface));
                // Surfaces share materials in a file; editing one surface gives it a material of its own.
                auto scene = std::make_shared<Scene>(*state.scene);
                Surface& surface = scene->surfaces[c.surface];
                Material edited = scene->materials[surface.material];
                edited.name = surface.name;
                edited.reflectance = c.reflectance;
                edited.exitance = c.exitance;
                surface.material = scene->materials.size();
                scene->materials.push_back(edited);
                state.scene = std::move(scene);
                if (state.solver) state.solver->setMaterial(c.surface, c.reflectance, c.exitance);
                state.history.materialEdited(surface.name, c.continuesEdit);
            } else if constexpr (std::is_same_v<C, command::ResetMaterials>) {
                if (!state.scene || !state.loadedScene) throw RadiantError({"", "reset materials"}, "no scene is loaded");
                // Same geometry (edits never change it): each edited surface takes its loaded
                // material back; the form factors and links stay.
                const Scene& loaded = *state.loadedScene;
                if (state.solver)
                    for (std::size_t s = 0; s < loaded.surfaces.size(); ++s) {
                        const Material& was = loaded.materials[loaded.surfaces[s].material];
                        const Material& is = state.scene->materials[state.scene->surfaces[s].material];
                        if (was.reflectance != is.reflectance || was.exitance.value() != is.exitance.value())
                            state.solver->setMaterial(s, was.reflectance, was.exitance);
                    }
                state.scene = state.loadedScene;
                state.running = false;
                state.pendingSteps = 0;
                if (state.solver) state.solver->reset();
                state.history.materialsRestored(state.method);
            } else if constexpr (std::is_same_v<C, command::Remesh> || std::is_same_v<C, command::LoadScene>) {
                std::shared_ptr<const Scene> scene = state.scene;
                std::shared_ptr<const RayCaster> rays = state.rays;
                if constexpr (std::is_same_v<C, command::LoadScene>) {
                    scene = c.scene;
                    state.loadedScene = c.scene;
                    state.view.reset();  // a camera of the old scene
                    rays.reset();
                }
                if (!scene) throw RadiantError({"", "re-mesh"}, "no scene is loaded");
                activity_.store(SolverActivity::Meshing);
                if (!rays) rays = std::make_shared<const RayCaster>(*scene);
                progress_.cancelRequested.store(false);
                std::shared_ptr<const PatchMesh> mesh;
                try {
                    mesh = std::make_shared<const PatchMesh>(meshScene(*scene, c.meshing, &progress_, rays.get()));
                } catch (const Cancelled&) {
                    // Keep the newest scene, without a mesh (a consistent snapshot), and make sure it
                    // is meshed: by the newer Remesh or LoadScene in the queue, or else by this again.
                    state.scene = std::move(scene);
                    state.rays = std::move(rays);
                    state.mesh.reset();
                    state.groups.reset();
                    state.solver.reset();
                    ++state.meshGeneration;
                    state.running = false;
                    state.pendingSteps = 0;
                    state.history.clear(state.method);
                    requeueMeshingUnlessSuperseded(c.meshing);
                    throw;
                }
                state.scene = std::move(scene);
                state.rays = std::move(rays);
                state.mesh = std::move(mesh);
                state.meshing = c.meshing;
                ++state.meshGeneration;
                // A method picked for another scene stays unless its matrix cannot hold this one:
                // opening a scene never ends in a refusal (re-meshing finer may, naming the slider).
                const bool pickDoesNotFit = std::is_same_v<C, command::LoadScene> &&
                                            methodInfo(state.method).traits.formFactorMatrix &&
                                            formFactorMatrixPeakBytes(state.mesh->size()) > options_.matrixBudgetBytes;
                if (pickDoesNotFit) state.methodPicked = false;
                startNewSystem(state);
            }
        },
        command);
}

void SolverThread::ensureSolver(State& state) {
    if (state.solver || !state.scene || !state.mesh) return;
    activity_.store(SolverActivity::FormFactors);
    progress_.cancelRequested.store(false);
    progress_.done.store(0);
    progress_.total.store(0);
    state.solver.reset();
    state.solverScene = state.scene;
    state.solverMesh = state.mesh;
    state.solverGroups = state.groups;
    ++state.solverBuilds;
    state.linksStale = true;
    SolverOptions options = options_;
    if (state.view) options.view = state.view;
    options.rays = state.rays;
    const bool gathering = state.method == SolverMethod::Jacobi || state.method == SolverMethod::GaussSeidel;
    if (state.keptMatrixMesh != state.mesh) {  // a new mesh: the kept form factors are another mesh's
        state.keptMatrix.reset();
        state.keptMatrixMesh.reset();
    }
    if (!state.solverGroups && gathering && state.keptMatrix) {
        // The materials as the factories make them: with the punctual lights' shadow rays.
        PatchMaterials materials = PatchMaterials::from(*state.solverScene, *state.solverMesh, options.rays.get());
        state.solver = state.method == SolverMethod::Jacobi ? makeJacobiSolver(std::move(materials), state.keptMatrix)
                                                            : makeGaussSeidelSolver(std::move(materials), state.keptMatrix);
    } else {
        state.solver = state.solverGroups ? makeGroupedSolver(state.method, *state.solverScene, *state.solverMesh,
                                                              state.solverGroups, options, &progress_)
                                          : factory_(state.method, *state.solverScene, *state.solverMesh, options, &progress_);
    }
    activity_.store(SolverActivity::Idle);
}

void SolverThread::publishOverlays(State& state, Snapshot& s) {
    const HierarchicalSolver* hierarchical = state.solver ? state.solver->hierarchy() : nullptr;
    if (!hierarchical) {
        state.linkSegments.reset();
        state.linkSolver = nullptr;
        state.focusSegments.reset();
        state.focusStale = true;
        return;
    }
    if (state.linksStale || state.linkSolver != hierarchical || state.linkCount != hierarchical->links().size()) {
        state.linkSegments = linkSegments(*hierarchical);
        state.linkSolver = hierarchical;
        state.linkCount = hierarchical->links().size();
        state.linksStale = false;
        state.focusStale = true;
    }
    s.linkSegments = state.linkSegments;
    if (state.focusStale) {
        state.focusSegments.reset();
        state.focusLevels = 0;
        if (state.focus && state.focus->meshGeneration == state.meshGeneration)
            std::tie(state.focusSegments, state.focusLevels) = focusLinkSegments(*hierarchical, *state.focus);
        state.focusStale = false;
    }
    s.focusLinkSegments = state.focusSegments;
    s.focusLevels = state.focusLevels;
    if (const std::span<const double> importance = state.solver->importance();
        !importance.empty() && importance.size() == s.radiosity.size())
        s.importance = std::make_shared<const std::vector<double>>(importance.begin(), importance.end());
}

void SolverThread::publish(State& state) {
    auto s = std::make_shared<Snapshot>();
    s->generation = ++state.generation;
    s->meshGeneration = state.meshGeneration;
    s->scene = state.scene;
    s->mesh = state.mesh;
    s->rays = state.rays;
    if (state.solver)
        s->radiosity = state.solver->solution();
    else if (state.scene && state.mesh)
        s->radiosity = emittedRadiosity(*state.scene, *state.mesh);
    // NaN or infinity must never reach the display (a diverging solve, a corrupt material): keep the
    // last finite picture of this mesh, show the error and stop stepping.
    if (const std::size_t bad = firstNonFinite(s->radiosity); bad != std::string::npos) {
        const Rgb& b = s->radiosity[bad];
        state.error = "the solution is no longer finite (patch " + std::to_string(bad) + ": " + std::to_string(b.x) + ", " +
                      std::to_string(b.y) + ", " + std::to_string(b.z) + " W/m^2); stopped: reset, or change the material or method";
        state.running = false;
        state.pendingSteps = 0;
        const std::shared_ptr<const Snapshot> previous = snapshot();
        if (previous->mesh == s->mesh && firstNonFinite(previous->radiosity) == std::string::npos)
            s->radiosity = previous->radiosity;
        else
            s->radiosity.clear();  // "no solution yet" to the display
    }
    s->method = state.method;
    s->methodReason = state.methodReason;
    if (state.solver) s->stats = state.solver->lastStats();
    s->history = state.history.steps().snapshot();
    s->convergence = state.history.snapshot();
    s->running = state.running || state.pendingSteps > 0;
    s->lastStepByHand = state.lastStepByHand;
    s->tolerance = state.tolerance;
    s->linkTolerance = options_.linkEpsilon;
    s->error = state.error;
    s->solverBuilds = state.solverBuilds;
    s->meshing = state.meshing;
    s->groups = state.groups;
    s->groupingReason = state.groupingReason;
    s->methodTakesNoGroups = state.methodTakesNoGroups;
    publishOverlays(state, *s);
    generationPublished_.store(s->generation, std::memory_order_relaxed);
    std::shared_ptr<const Snapshot> next(std::move(s));
    {
        std::lock_guard lock(publishedMutex_);
        published_.swap(next);
    }
    // `next` now holds the previous snapshot and is released here, outside the lock.
    state.lastPublish = std::chrono::steady_clock::now();
}

} // namespace radiant::app
