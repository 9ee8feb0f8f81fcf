#include "app/LabApp.h"

#include <cstdio>

namespace radiant::app {

// PLACEHOLDER until the first window lands.
int runLab(const LabOptions&) {
    std::fprintf(stderr, "radiant: the window is not available in this build yet\n");
    return 2;
}

} // namespace radiant::app
