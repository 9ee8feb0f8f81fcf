// The sidebar on a projector: every panel and every lecture demo open, at UI scales 1.0, 1.5 and 2.0
// in a 1600 x 1000 window, and no text cut off by the sidebar's edge or by a table column
// (app/ui/ClippedText.h reads both from ImGui's own layout of the frame just drawn).
#include <doctest/doctest.h>

#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/Lab.h"
#include "app/ui/ClippedText.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;

using radiant::test::frameUntil;

namespace {

/// Draws a few frames (a focus request applies on the next one; tables settle their columns on the
/// one after), then returns what the last of them cut off.
std::vector<app::ui::ClippedText> settleAndCheck(Lab& lab) {
    for (int frame = 0; frame < 4; ++frame) lab.frame();
    return app::ui::findClippedText();
}

void report(const std::vector<app::ui::ClippedText>& clipped, float scale, const std::string& open) {
    for (const app::ui::ClippedText& c : clipped)
        FAIL_CHECK("UI scale " << scale << ", " << open << " open: " << c.where << " is cut off by "
                                   << c.pixels << " px");
}

} // namespace

TEST_SUITE("gl sidebar") {

TEST_CASE("every panel and lecture demo fits the sidebar at UI scales 1.0, 1.5 and 2.0 in 1600 x 1000") {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) FAIL("no X display: run the GL tests under Xvfb (scripts/test does: xvfb-run -a)");
    const std::vector<std::string> panels = {"Scene", "Solver", "Materials", "Probe", "Display", "Info",
                                             "Hemisphere", "Integrals", "Lecture demos"};
    LabOptions options;
    options.width = 1600;
    options.height = 1000;
    options.vsync = false;
    options.maxPatchArea = 0.05;  // about a hundred patches: the layout, not the solve, is under test
    Lab lab(options);
    frameUntil(lab, [&] { const auto s = lab.snapshot(); return s->mesh && s->stats.iteration > 0 && !s->running; });
    // A probed point fills the Probe, Hemisphere and Integrals panels with their readings and tables.
    const glm::dvec3 floorPoint{0.42, 0.0, 0.12};
    const glm::dvec3 pixel = render::projectToPixel(lab.camera(), lab.sceneViewport(), floorPoint);
    REQUIRE(lab.clickAt({pixel.x, pixel.y}));
    frameUntil(lab, [&] { return lab.probeReading().has_value(); });

    // One lab at three scales, as the Display panel's slider changes it (a lab per scale would also
    // reconnect to the X server while it resets after the previous one left).
    float fontAtScaleOne = 0;
    for (const float scale : {1.0f, 1.5f, 2.0f}) {
        CAPTURE(scale);
        lab.display().uiScale = scale;
        lab.focusPanel("");  // everything open at once, as a lecturer scrolls through it
        report(settleAndCheck(lab), scale, "every panel");
        if (scale == 1.0f) fontAtScaleOne = ImGui::GetFontSize();
        CHECK(ImGui::GetFontSize() == doctest::Approx(scale * fontAtScaleOne).epsilon(0.05).scale(0));
        for (const std::string& panel : panels) {  // and one at a time, so a failure names its panel
            lab.focusPanel(panel);
            report(settleAndCheck(lab), scale, "panel '" + panel + "'");
        }
    }
}

} // TEST_SUITE
