#pragma once
// The interactive lab: the window, the frame loop and the panels.
#include <optional>
#include <string>

#include "radiometry/solver/SolveDefaults.h"

namespace radiant::app {

struct LabOptions {
    std::string scene = "cornell-box";
    int width = 1600;
    int height = 1000;
    bool showPanels = true;  ///< false: the 3D view fills the window (pixel tests, clean captures)
    bool visible = true;     ///< false: an offscreen window (tests that need no display output)
    bool vsync = true;
    float uiScale = 1.0f;    ///< ImGui text and spacing scale; RADIANT_UI_SCALE overrides it in runLab
    /// m^2 for every scene opened; none: each scene opens at openingPatchArea's for its size
    /// (OpeningPatchArea.h: the Cornell box at kSolveDefaults.maxPatchArea).
    std::optional<double> maxPatchArea;
    bool runOnStart = true;      ///< solve as soon as the form factors are ready; false waits for Run/Step
    std::string lesson;          ///< a lesson file to open on its first step (docs/lessons.md); empty: none
};

/// Opens the window and runs until it is closed. Returns the process exit status.
int runLab(const LabOptions& options);

} // namespace radiant::app
