#pragma once
// What a lesson acts on in the lab: its solver thread, sidebar, lecture demos, probe, camera and
// display settings (LessonPlayer.h). Held by the lab, called from its frame loop.
#include <cstdint>
#include <memory>
#include <string>

#include "app/lessons/LessonPlayer.h"
#include "app/solver/LiveSolve.h"
#include "radiometry/scene/Scene.h"
#include "render/DisplaySettings.h"
#include "render/camera/OrbitCamera.h"

namespace radiant::app {

class Sidebar;
class LectureDemosPanel;
class ProbePanel;
class IntegralsPanel;

class LabLessonStage final : public LessonStage {
public:
    /// Keeps references; `patchArea` (m^2) is what scenes are meshed with, and a remesh updates it.
    LabLessonStage(LiveSolve& live, Sidebar& sidebar, LectureDemosPanel& demos, ProbePanel& probe,
                   IntegralsPanel& integrals, render::OrbitCamera& orbit, render::DisplaySettings& display,
                   double& patchArea)
        : live_(live), sidebar_(sidebar), demos_(demos), probe_(probe), integrals_(integrals), orbit_(orbit),
          display_(display), patchArea_(patchArea) {}

    void loadScene(const std::string& nameOrPath) override;
    void remesh(double maxPatchAreaM2) override;
    [[nodiscard]] bool sceneReady() const override;
    void openDemo(const std::string& id) override;
    void send(SolverCommand command) override;
    void setMaterial(const lesson::SetMaterial& edit) override;
    void placeCamera(const lesson::PlaceCamera& place) override;
    bool probe(const lesson::Probe& at) override;
    void openPanel(const std::string& title) override;
    render::DisplaySettings& display() override { return display_; }
    void compare(const std::optional<ComparisonSettings>& settings) override;
    void setIntegrals(const lesson::SetIntegrals& integrals) override;

private:
    LiveSolve& live_;
    Sidebar& sidebar_;
    LectureDemosPanel& demos_;
    ProbePanel& probe_;
    IntegralsPanel& integrals_;
    render::OrbitCamera& orbit_;
    render::DisplaySettings& display_;
    double& patchArea_;
    std::shared_ptr<const Scene> awaitedScene_;  ///< the scene a load waits to see shown; null after a remesh
    std::uint64_t awaitedAfter_ = 0;      ///< the mesh generation shown when the lesson asked for a new one
};

} // namespace radiant::app
