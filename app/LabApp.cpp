#include "app/LabApp.h"

#include <cstdlib>
#include <string>

#include "app/Lab.h"

namespace radiant::app {

int runLab(const LabOptions& options) {
    LabOptions effective = options;
    if (const char* scale = std::getenv("RADIANT_UI_SCALE")) effective.uiScale = std::strtof(scale, nullptr);
    if (!(effective.uiScale > 0.0f)) effective.uiScale = 1.0f;
    Lab lab(effective);
    while (!lab.shouldClose()) lab.frame();
    return 0;
}

} // namespace radiant::app
