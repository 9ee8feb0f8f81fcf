#pragma once
// A saved session: the lab's state (scene, meshing, method and tolerances, every surface's material
// as edited, camera, probe, display) written as a one-step lesson file marked "session", so it is
// read, checked and played by the same code as lessons (docs/lessons.md), and its step can be
// pasted into a lesson.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/lessons/Lesson.h"
#include "app/panels/ProbePanel.h"
#include "app/solver/Snapshot.h"
#include "render/DisplaySettings.h"
#include "render/camera/Camera.h"

namespace radiant::app::lesson {

struct SessionState {
    std::string scene;  ///< a built-in name, or an absolute glTF path
    double maxPatchAreaM2 = 0;
    SolverMethod method = SolverMethod::GaussSeidel;
    double tolerance = 0;
    double linkTolerance = 0;
    std::vector<SetMaterial> materials;  ///< every surface, as the lab has it
    PlaceCamera camera;
    std::optional<Probe> probe;
    SetDisplay display;
    Compare comparison;  ///< B's method, mesh and view while two methods are compared
};

/// The session as lesson JSON; `savedAt` names the moment in its step's title.
std::string sessionText(const SessionState& state, const std::string& savedAt);

/// The lab's state: what the snapshot shows (scene, mesh, method, tolerances, materials as edited),
/// the camera and its pivot, the probe's pick and target, the display settings, the comparison
/// (nullopt: none). Throws RadiantError before a scene is shown.
SessionState captureSession(const Snapshot& shown, const render::Camera& camera, const glm::dvec3& pivot,
                            const std::optional<ProbePick>& pick, const std::optional<std::string>& target,
                            const render::DisplaySettings& display,
                            const std::optional<ComparisonSettings>& comparison = std::nullopt);
/// Writes it to `path`, or when empty to radiant-session-YYYYMMDD-HHMMSS.json in the working folder;
/// returns the absolute path. Throws RadiantError naming the file when it cannot.
std::filesystem::path writeSession(const SessionState& state, const std::string& path);

} // namespace radiant::app::lesson
