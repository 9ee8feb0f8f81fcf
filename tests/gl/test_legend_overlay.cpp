// The false-colour legend where people look: in the real lab's 3D view, at a projector's UI scale,
// a vertical colour bar runs from viridis' top colour (the maximum) down to its bottom one in the view's
// top-right corner; tone-mapped, no such bar is there (so the search below can fail).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "app/Lab.h"
#include "app/solver/SolverThread.h"
#include "render/ColourScale.h"
#include "render/Screenshot.h"
#include "tests/gl/FrameUntil.h"

using namespace radiant;
using radiant::app::Lab;
namespace command = radiant::app::command;

namespace {

struct BarFound {
    int x = 0, top = 0, bottom = 0;
};

bool near(const render::ImageRgb8& image, int x, int y, double t, double tolerance) {
    const glm::dvec3 expected = render::viridis(t) * 255.0;
    const glm::u8vec3 p = image.at(x, y);
    return std::abs(p.x - expected.x) <= tolerance && std::abs(p.y - expected.y) <= tolerance &&
           std::abs(p.z - expected.z) <= tolerance;
}

/// A column in the right half whose pixels go from viridis(1) at the top through viridis(0.5) halfway
/// to viridis(0) at least `minLength` pixels below: the legend's bar.
std::optional<BarFound> findColourBar(const render::ImageRgb8& image, int minLength) {
    for (int x = image.width - 1; x >= image.width / 2; --x)
        for (int y = 0; y < image.height / 2; ++y) {
            if (!near(image, x, y, 1.0, 8)) continue;
            int bottom = -1;
            for (int y2 = y + minLength; y2 < image.height; ++y2)
                if (near(image, x, y2, 0.0, 8)) bottom = y2;
                else if (bottom >= 0) break;
            if (bottom < 0) continue;
            if (near(image, x, (y + bottom) / 2, 0.5, 12)) return BarFound{x, y, bottom};
        }
    return std::nullopt;
}

void frameUntilConverged(Lab& lab) {
    radiant::test::frameUntil(lab, [](const app::Snapshot& s) { return s.mesh && s.solverBuilds >= 1 && !s.running && s.stats.iteration > 0; },
                              "a converged solve");
}

} // namespace

TEST_SUITE("gl lab") {

TEST_CASE("the false-colour legend is drawn in the 3D view's top-right corner at UI scales 1.0 and 1.5, and only in false colour") {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) FAIL("no X display: run the GL tests under Xvfb (scripts/test does: xvfb-run -a)");
    app::LabOptions options;
    options.scene = "cornell-box";
    options.width = 1600;
    options.height = 1000;
    options.vsync = false;
    options.uiScale = 1.5f;
    options.maxPatchArea = 0.01;
    Lab lab(options);
    frameUntilConverged(lab);

    lab.display().colourMode = render::ColourMode::ToneMapped;
    CHECK_FALSE(findColourBar(lab.frameAndCapture(), 100).has_value());

    lab.display().colourMode = render::ColourMode::FalseColour;
    lab.display().isolines = true;
    for (const float scale : {1.0f, 1.5f}) {
        lab.display().uiScale = scale;
        for (int i = 0; i < 3; ++i) lab.frame();  // the font atlas is rebuilt at the new scale
        const render::ImageRgb8 image = lab.frameAndCapture();
        const std::optional<BarFound> bar = findColourBar(image, 100);
        INFO("UI scale " << scale);
        REQUIRE(bar.has_value());
        INFO("bar at x " << bar->x << ", rows " << bar->top << " to " << bar->bottom);
        // In the view's top-right corner (the sidebar is on the left), tall enough to read from afar.
        CHECK(bar->x > image.width * 3 / 4);
        CHECK(bar->top < image.height / 6);
        CHECK(bar->bottom - bar->top >= image.height / 4);
        if (const char* directory = std::getenv("RADIANT_SCREENSHOT_DIR"))
            render::writePng(image, std::filesystem::path(directory) /
                                        (scale == 1.5f ? "legend-3d-view.png" : "legend-3d-view-scale-1.png"));
    }
}

}
