#pragma once
// The interactive lab: the window, the frame loop and the panels.
#include <string>

namespace radiant::app {

struct LabOptions {
    std::string scene = "cornell-box";
    int width = 1600;
    int height = 1000;
};

/// Opens the window and runs until it is closed. Returns the process exit status.
int runLab(const LabOptions& options);

} // namespace radiant::app
