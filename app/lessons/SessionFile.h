#pragma once
// A saved session: the lab's state (scene, meshing, method and tolerances, every surface's material
// as edited, camera, probe, display) written as a one-step lesson file marked "session", so it is
// read, checked and played by the same code as lessons (docs/lessons.md), and its step can be
// pasted into a lesson.
#include <optional>
#include <string>
#include <vector>

#include "app/lessons/Lesson.h"

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
};

/// The session as lesson JSON; `savedAt` names the moment in its step's title.
std::string sessionText(const SessionState& state, const std::string& savedAt);

} // namespace radiant::app::lesson
