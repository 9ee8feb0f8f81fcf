#include "app/LabApp.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "app/Lab.h"
#include "app/lessons/Lesson.h"
#include "render/Screenshot.h"
#include "render/camera/Camera.h"

namespace radiant::app {
namespace {

std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

/// Hidden switches for documentation screenshots, taken without a human at the window:
///   RADIANT_SCREENSHOT=file.png   capture the whole window after RADIANT_SCREENSHOT_FRAMES frames
///                                 (default 120) and quit
///   RADIANT_PANEL=Title           expand only that panel
///   RADIANT_PROBE=x,y,z           click the scene where this world point (m) projects
struct Automation {
    std::string screenshot = environment("RADIANT_SCREENSHOT");
    long frames = std::strtol(environment("RADIANT_SCREENSHOT_FRAMES").c_str(), nullptr, 10);
    std::string panel = environment("RADIANT_PANEL");
    std::string probe = environment("RADIANT_PROBE");
};

} // namespace

int runLab(const LabOptions& options) {
    LabOptions effective = options;
    if (const char* scale = std::getenv("RADIANT_UI_SCALE")) effective.uiScale = std::strtof(scale, nullptr);
    if (!(effective.uiScale > 0.0f)) effective.uiScale = 1.0f;
    // A bad lesson file is refused before any window opens.
    if (!effective.lesson.empty()) (void)lesson::readLesson(effective.lesson);
    Lab lab(effective);
    if (!effective.lesson.empty()) lab.openLesson(effective.lesson);
    const Automation automation;
    if (!automation.panel.empty()) lab.focusPanel(automation.panel);
    const long captureAt = automation.frames > 0 ? automation.frames : 120;
    while (!lab.shouldClose()) {
        if (automation.screenshot.empty()) {
            lab.frameWhenNeeded();
            continue;
        }
        const auto frame = lab.frameCount();
        if (!automation.probe.empty() && frame == 2) {
            glm::dvec3 point(0.0);
            if (std::sscanf(automation.probe.c_str(), "%lf,%lf,%lf", &point.x, &point.y, &point.z) == 3) {
                const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), point);
                lab.clickAt({pixel.x, pixel.y});
            }
        }
        if (static_cast<long>(frame) < captureAt) {
            lab.frame();
            continue;
        }
        try {
            render::writePng(lab.frameAndCapture(), automation.screenshot);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "radiant: %s\n", e.what());
            return 2;
        }
        break;
    }
    return 0;
}

} // namespace radiant::app
