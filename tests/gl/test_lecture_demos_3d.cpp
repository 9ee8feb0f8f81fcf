// The lecture demos in the real lab's 3D view: each draws its own picture (checked by colours only
// that demo puts on screen), the point-source demo reads out E under the pointer, and closing a demo
// gives back the scene as it was: the same camera, the same solve, the same probe.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

#include "app/Lab.h"
#include "app/lessons/Lesson.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;

using radiant::test::frameUntil;
using radiant::test::requireDisplay;

namespace {

glm::dvec3 colourAt(const render::ImageRgb8& image, const glm::dvec3& pixel, int r = 2) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = static_cast<int>(pixel.y) - r; y <= static_cast<int>(pixel.y) + r; ++y)
        for (int x = static_cast<int>(pixel.x) - r; x <= static_cast<int>(pixel.x) + r; ++x) {
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
            sum += glm::dvec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
            ++count;
        }
    return count ? sum / static_cast<double>(count) : sum;
}

/// Pixels of the 3D view within `tolerance` (per channel, 0..255) of an sRGB colour given in 0..1.
int pixelsNear(const render::ImageRgb8& image, const render::Viewport& view, const glm::dvec3& colour, double tolerance = 30) {
    int count = 0;
    for (int y = view.y; y < view.y + view.height; ++y)
        for (int x = view.x; x < view.x + view.width; ++x) {
            const glm::dvec3 c = colourAt(image, {x, y, 0}, 0);
            const glm::dvec3 d = glm::abs(c - 255.0 * colour);
            if (d.x <= tolerance && d.y <= tolerance && d.z <= tolerance) ++count;
        }
    return count;
}

glm::dvec3 at(Lab& lab, const glm::dvec3& world) { return render::projectToPixel(lab.camera(), lab.sceneViewport(), world); }

double brightness(const glm::dvec3& c) { return c.x + c.y + c.z; }

} // namespace

TEST_SUITE("gl lecture demos") {

TEST_CASE("each lecture demo draws in the 3D view, and the scene, its solve, camera and probe come back when it closes") {
    requireDisplay();
    LabOptions options;
    options.width = 1400;
    options.height = 900;
    options.vsync = false;
    options.maxPatchArea = 0.05;
    Lab lab(options);
    frameUntil(lab, [&] { const auto s = lab.snapshot(); return s->mesh && s->stats.iteration > 0 && !s->running; });
    const glm::dvec3 floorPoint{0.42, 0.0, 0.12};
    const glm::dvec3 pixel = at(lab, floorPoint);
    REQUIRE(lab.clickAt({pixel.x, pixel.y}));
    frameUntil(lab, [&] { return lab.probeReading().has_value(); });
    lab.frame();  // the pick goes to the solver thread (its focused links), which publishes once more
    lab.waitForSolver();
    lab.frame();
    const render::Camera before = lab.camera();
    const auto solved = lab.snapshot();
    const glm::dvec3 probed = lab.probeReading()->at.point;
    const render::ImageRgb8 sceneImage = lab.frameAndCapture();

    for (const std::string& id : app::lesson::demoIds()) {
        CAPTURE(id);
        lab.openDemo(id);
        for (int i = 0; i < 3; ++i) lab.frame();
        REQUIRE(lab.activeDemo() == id);
        CHECK(glm::length(lab.camera().eye - before.eye) > 0.1);  // the demo's own framing
        const render::ImageRgb8 image = lab.frameAndCapture();
        const render::Viewport view = lab.sceneViewport();
        if (id == "point-source") {
            // Viridis' yellow-green near the top beside the source's foot (E = 0.81 of the peak; the
            // labels run to the right, clear of it), its dark end at a far corner.
            const glm::dvec3 under = colourAt(image, at(lab, {-0.3, 0, 0.25})), far = colourAt(image, at(lab, {-4.6, 0, -3.2}));
            CHECK(under.y > under.z + 60);  // green-yellow, where the dark end is purple
            CHECK(under.y > 170);
            CHECK(brightness(under) > brightness(far) + 200);
        } else if (id == "diffuse-emitter") {
            const glm::dvec3 emitter = colourAt(image, at(lab, {0.2, 0, 0.2}));
            CHECK(emitter.x > 150);
            CHECK(emitter.z < 0.6 * emitter.x);  // the emitter's warm light, not the grey backdrop
        } else if (id == "sun") {
            const glm::dvec3 sun = colourAt(image, at(lab, {0, 0, 0}));
            CHECK(sun.x > 150);
            CHECK(sun.z < 0.6 * sun.x);
        } else if (id == "square-solid-angle") {
            // The square's projection onto the unit hemisphere, straight above the point.
            const glm::dvec3 patch = colourAt(image, at(lab, glm::normalize(glm::dvec3{0.3, 2.0, 0.3})));
            CHECK(patch.x > 200);
            CHECK(patch.y < 160);
            CHECK(patch.z < 80);
        } else if (id == "dodecahedron") {
            CHECK(pixelsNear(image, view, {1.0, 0.45, 0.10}) > 2000);  // the highlighted face, solid orange
        } else if (id == "radiance-irradiance") {
            const glm::dvec3 receiver = colourAt(image, at(lab, {0.3, 0.15, 0.25}));
            CHECK(brightness(receiver) > 300);  // lit at 30 degrees: 0.87 of full
        }
    }

    {  // the point-source demo reads out E under the pointer
        lab.openDemo("point-source");
        lab.frame();
        const glm::dvec3 spot = at(lab, {2.0, 0, -1.0});
        const render::Viewport view = lab.sceneViewport();
        lab.overrideMouse(glm::vec2(static_cast<float>(view.x + 5), 5.0f));  // over the view, off the plane
        lab.frame();
        const render::ImageRgb8 without = lab.frameAndCapture();
        const int cyanBefore = pixelsNear(without, lab.sceneViewport(), {0.35, 0.85, 1.0}, 25);
        lab.overrideMouse(glm::vec2(static_cast<float>(spot.x), static_cast<float>(spot.y)));
        lab.frame();
        const render::ImageRgb8 with = lab.frameAndCapture();
        lab.overrideMouse(std::nullopt);
        CHECK(pixelsNear(with, lab.sceneViewport(), {0.35, 0.85, 1.0}, 25) > cyanBefore + 100);  // ring, ray and reading
    }

    lab.closeDemo();
    for (int i = 0; i < 3; ++i) lab.frame();
    CHECK(lab.activeDemo().empty());
    CHECK(glm::length(lab.camera().eye - before.eye) < 1e-12);
    CHECK(glm::length(lab.camera().forward - before.forward) < 1e-12);
    // The solve untouched: the same iteration and the same radiosity, patch by patch.
    CHECK(lab.snapshot()->stats.iteration == solved->stats.iteration);
    CHECK(lab.snapshot()->radiosity == solved->radiosity);
    REQUIRE(lab.probeReading().has_value());
    CHECK(glm::length(lab.probeReading()->at.point - probed) < 1e-12);
    // The 3D view as it was (the sidebar shows the demos' header open now, so only the view is compared).
    const render::ImageRgb8 back = lab.frameAndCapture();
    REQUIRE(back.pixels.size() == sceneImage.pixels.size());
    const render::Viewport view = lab.sceneViewport();
    double difference = 0;
    for (int y = view.y; y < view.y + view.height; ++y)
        for (int x = view.x; x < view.x + view.width; ++x)
            difference += glm::length(colourAt(back, {x, y, 0}, 0) - colourAt(sceneImage, {x, y, 0}, 0));
    CHECK(difference / (static_cast<double>(view.width) * view.height) < 1.0);  // the same picture, to a level or so
}

TEST_CASE("folding the demos' header away, or a lesson loading a scene, closes the demo") {
    requireDisplay();
    LabOptions options;
    options.width = 1000;
    options.height = 700;
    options.vsync = false;
    options.maxPatchArea = 0.05;
    options.runOnStart = false;
    Lab lab(options);
    frameUntil(lab, [&] { return lab.snapshot()->mesh != nullptr; });
    lab.frame();
    const render::Camera before = lab.camera();
    lab.openDemo("sun");
    lab.frame();
    REQUIRE(lab.activeDemo() == "sun");
    lab.focusPanel("Probe");  // the "Lecture demos" header folds
    for (int i = 0; i < 3; ++i) lab.frame();
    CHECK(lab.activeDemo().empty());
    CHECK(glm::length(lab.camera().eye - before.eye) < 1e-12);

    lab.openDemo("no-such-demo");
    lab.frame();
    CHECK(lab.activeDemo().empty());
}

} // TEST_SUITE
