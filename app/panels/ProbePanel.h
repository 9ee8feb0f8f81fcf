#pragma once
// Probe: what a small detector at the clicked point would read - B, L = B/pi, the irradiance E
// gathered at that exact point, the reflectance, and for a chosen target surface its solid angle,
// projected solid angle and form factor (radiometry/probe/Probe.h). The readings follow the solve:
// they are recomputed on a worker when a newer snapshot arrives, at most a few times a second.
// Beside them, the same point path-traced (PathTracedReading.h): an independent reference that
// shows the discretisation error of the method chosen.
#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "app/panels/Panel.h"
#include "app/panels/PathTracedReading.h"
#include "app/solver/LiveSolve.h"
#include "radiometry/probe/Probe.h"
#include "render/DisplaySettings.h"

namespace radiant::app {

/// A point picked on the scene: a ray hit, kept while the mesh it was picked on is shown.
struct ProbePick {
    glm::dvec3 point{0.0};       ///< metres
    glm::dvec3 normal{0, 0, 1};  ///< unit, the face's front side
    std::uint32_t surface = 0;
    std::uint32_t face = 0;  ///< within the surface
    std::uint64_t meshGeneration = 0;
};

class ProbePanel final : public Panel {
public:
    explicit ProbePanel(LiveSolve& live);
    ~ProbePanel() override;

    [[nodiscard]] const char* title() const override { return "Probe"; }
    void update() override;
    void draw() override;
    /// A measurement in flight or due: its reading arrives without input.
    [[nodiscard]] bool busy() const override;
    [[nodiscard]] bool refreshesUnprompted() const override { return pick_ && pathTraced_.state().refining; }

    /// Casts the ray into the current scene and probes the nearest hit; false when it hits nothing.
    bool pick(const glm::dvec3& origin, const glm::dvec3& direction);
    [[nodiscard]] const std::optional<ProbePick>& picked() const { return pick_; }
    /// The newest finished reading and the snapshot generation it was measured on.
    [[nodiscard]] const std::optional<ProbeReading>& reading() const { return reading_; }
    [[nodiscard]] std::uint64_t readingGeneration() const { return readingGeneration_; }
    /// Comparison mode: the same point read on solution B (LiveSolve::secondCurrent).
    [[nodiscard]] const std::optional<ProbeReading>& secondReading() const { return secondReading_; }
    /// Chooses the target surface by index (the combo does this too).
    void setTarget(std::size_t surface);
    /// The display settings whose units switch adds lx and cd/m^2 rows (kept by reference).
    void followUnits(const render::DisplaySettings& display) { display_ = &display; }
    /// The `radiant probe ...` line that repeats this reading (ProbeCommandLine.h); empty with no pick.
    [[nodiscard]] std::string commandLine() const;

    /// Readings are refreshed at most this often while the solve runs,
    static constexpr std::chrono::milliseconds kRefreshInterval{250};
    /// and at most once in this many times the last measurement's wall time: on a fine mesh a
    /// gather (two in comparison mode) takes tens of milliseconds, and four a second kept about a
    /// tenth of a core from the 3D view's rasterisers while the solve ran (`radiant bench --only
    /// frames`). Measured in wall time, it backs off further when the machine is busy.
    static constexpr double kMeasureShare = 8.0;
    /// The wait between refreshes after a measurement that took `lastMeasureSeconds`.
    [[nodiscard]] static std::chrono::duration<double> refreshInterval(double lastMeasureSeconds);

private:
    /// What the worker hands back: a reading, or why there is none.
    struct Measured {
        std::optional<ProbeReading> reading;
        std::string error;
        std::uint64_t generation = 0;
        double seconds = 0;
        std::optional<ProbeReading> secondReading;  ///< comparison mode: on solution B
        std::uint64_t secondGeneration = 0;
    };
    void startMeasuring(std::chrono::steady_clock::time_point now);
    void drawReadings(const Scene& scene, const ProbeReading& reading);
    void drawTarget(const Scene& scene);
    void drawPathTraced(const ProbeReading& reading);
    void drawCopyCommand();
    /// Comparison mode: A's and B's values at the point and how far apart they are.
    /// A's and B's values at the point and their differences, or why there are none yet.
    void drawComparison(const ProbeReading& a, const Snapshot& secondSnapshot);
    /// B's snapshot generation, or 0 with the comparison off.
    [[nodiscard]] std::uint64_t secondGeneration() const;
    /// Starts the path tracer at the pick, or restarts it when the materials changed under it.
    void followPathTraced(const std::shared_ptr<const Snapshot>& snapshot);

    LiveSolve& live_;
    std::optional<ProbePick> pick_;
    std::optional<std::size_t> target_;
    std::uint64_t targetMesh_ = 0;  ///< mesh generation target_ was chosen for
    std::optional<ProbeReading> reading_;
    std::uint64_t readingGeneration_ = 0;
    std::optional<ProbeReading> secondReading_;
    std::uint64_t secondReadingGeneration_ = 0;
    std::string error_;
    double measureSeconds_ = 0;
    bool dirty_ = false;  ///< the pick or target changed since the last measurement started
    std::future<Measured> job_;
    std::chrono::steady_clock::time_point lastStart_{};
    PathTracedReading pathTraced_;  ///< last: its worker reads the snapshot's rays
    bool pathTracedCurrent_ = false;  ///< pathTraced_ runs at pick_
    const render::DisplaySettings* display_ = nullptr;
    bool copied_ = false;  ///< "Copy as command" was pressed for this pick
};

} // namespace radiant::app
