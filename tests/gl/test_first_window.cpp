// The first window, driven frame by frame under Xvfb: the Cornell box must appear where the
// Cornell camera puts it. Expected pixel positions come from projecting known wall points
// (docs/reference.md's measured box, in metres) with the camera the lab reports.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <glm/vec3.hpp>
#include <string>

#include "app/Lab.h"
#include "app/solver/Snapshot.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using radiant::app::Lab;
using radiant::app::LabOptions;
using radiant::render::ImageRgb8;
using radiant::render::Viewport;
using radiant::test::requireDisplay;

namespace {

struct MeanColour {
    double r = 0, g = 0, b = 0;
    [[nodiscard]] double min() const { return std::min({r, g, b}); }
    [[nodiscard]] double max() const { return std::max({r, g, b}); }
};

/// Mean colour of the (2 radius + 1)^2 pixels around (x, y).
MeanColour meanAround(const ImageRgb8& image, double x, double y, int radius = 4) {
    const int cx = static_cast<int>(x), cy = static_cast<int>(y);
    INFO("region around (", x, ", ", y, ") in a ", image.width, " x ", image.height, " image");
    REQUIRE(cx - radius >= 0);
    REQUIRE(cy - radius >= 0);
    REQUIRE(cx + radius < image.width);
    REQUIRE(cy + radius < image.height);
    MeanColour mean;
    int count = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const glm::u8vec3 c = image.at(cx + dx, cy + dy);
            mean.r += c.x;
            mean.g += c.y;
            mean.b += c.z;
            ++count;
        }
    mean.r /= count;
    mean.g /= count;
    mean.b /= count;
    return mean;
}

std::string describe(const MeanColour& c) {
    return "rgb(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

// Points on the measured box (mm / 1000), chosen where no block stands between them and the
// Cornell eye: the blocks top out at y = 0.165 and 0.33 m, these wall points are at y = 0.45 m.
const glm::dvec3 kRedWall{0.552, 0.45, 0.40};
const glm::dvec3 kGreenWall{0.0, 0.45, 0.40};
const glm::dvec3 kBackWall{0.278, 0.45, 0.5592};
const glm::dvec3 kFloor{0.42, 0.0, 0.15};  // right of the short block, in front of the tall one
const glm::dvec3 kRedWallFrontBottom{0.5528, 0.0, 0.0};

/// Checks the Cornell box's layout in `image`, whose 3D view is `view` drawn with `camera`.
void checkCornellImage(const ImageRgb8& image, const radiant::render::Camera& camera, const Viewport& view) {
    const auto at = [&](const glm::dvec3& p) { return radiant::render::projectToPixel(camera, view, p); };
    const glm::dvec3 red = at(kRedWall), green = at(kGreenWall), back = at(kBackWall), floor = at(kFloor);
    const double centreX = view.x + view.width / 2.0;

    // Camera convention, independently of the projection code: looking along +z with +y up, +x is
    // on the left, so the red wall (x = 0.55 m) is left of centre and the green (x = 0) right.
    CHECK(red.x < centreX);
    CHECK(green.x > centreX);
    CHECK(floor.y > back.y);  // rows count down

    {
        const MeanColour redPixels = meanAround(image, red.x, red.y);
        INFO("red wall at (", red.x, ", ", red.y, "): ", describe(redPixels));
        CHECK(redPixels.r > 100);
        CHECK(redPixels.r > 2.0 * redPixels.g);
        CHECK(redPixels.r > 2.0 * redPixels.b);
    }

    {
        const MeanColour greenPixels = meanAround(image, green.x, green.y);
        INFO("green wall at (", green.x, ", ", green.y, "): ", describe(greenPixels));
        CHECK(greenPixels.g > 80);
        CHECK(greenPixels.g > 1.4 * greenPixels.r);
        CHECK(greenPixels.g > 1.4 * greenPixels.b);
    }

    // White reflectance (0.73, 0.71, 0.68): a light, nearly neutral grey.
    {
        const MeanColour backPixels = meanAround(image, back.x, back.y);
        INFO("back wall at (", back.x, ", ", back.y, "): ", describe(backPixels));
        CHECK(backPixels.min() > 140);
        CHECK(backPixels.max() - backPixels.min() < 30);
    }

    {
        const MeanColour floorPixels = meanAround(image, floor.x, floor.y);
        INFO("floor at (", floor.x, ", ", floor.y, "): ", describe(floorPixels));
        CHECK(floorPixels.min() > 100);
        CHECK(floorPixels.max() - floorPixels.min() < 30);
    }

    // Aspect correction: a wide view shows background beside the box, halfway between the view's
    // left edge and the red wall's front edge.
    const glm::dvec3 edge = at(kRedWallFrontBottom);
    REQUIRE(edge.x > view.x + 20);
    const MeanColour outside = meanAround(image, (view.x + edge.x) / 2.0, view.y + view.height / 2.0, 2);
    INFO("beside the box: ", describe(outside));
    CHECK(outside.max() < 40);
}

/// The solver thread meshes the scene while the window already draws: wait until a frame has drawn
/// the mesh.
void waitForMesh(Lab& lab) { radiant::test::frameUntil(lab, [&] { return lab.snapshot() && lab.snapshot()->mesh; }, "a mesh"); }

} // namespace

TEST_SUITE("gl window") {

TEST_CASE("the first window draws the Cornell box as the Cornell camera sees it") {
    requireDisplay();
    LabOptions options;
    options.maxPatchArea = 0.01;  // coarse: quick to mesh and solve
    options.width = 960;
    options.height = 600;
    options.showPanels = false;
    Lab lab(options);
    // The layout check reads material colours: show reflectance, not the (still dark) solution.
    lab.display().colourMode = radiant::render::ColourMode::Reflectance;
    lab.display().highlightShooter = false;  // the default method shoots: its shooter's outline is orange
    waitForMesh(lab);
    CHECK(lab.glInfo().major * 10 + lab.glInfo().minor >= 33);
    ImageRgb8 image;
    for (int i = 0; i < 3; ++i) image = lab.frameAndCapture();
    REQUIRE(image.width == options.width);
    REQUIRE(image.height == options.height);
    const Viewport view = lab.sceneViewport();
    CHECK(view.x == 0);
    CHECK(view.width == image.width);
    checkCornellImage(image, lab.camera(), view);
}

TEST_CASE("with the panels docked on the left the box keeps its layout in the remaining view") {
    requireDisplay();
    LabOptions options;
    options.maxPatchArea = 0.01;  // coarse: quick to mesh and solve
    options.width = 1200;
    options.height = 700;
    Lab lab(options);
    // The layout check reads material colours: show reflectance, not the (still dark) solution.
    lab.display().colourMode = radiant::render::ColourMode::Reflectance;
    lab.display().highlightShooter = false;  // the default method shoots: its shooter's outline is orange
    waitForMesh(lab);
    ImageRgb8 image;
    for (int i = 0; i < 3; ++i) image = lab.frameAndCapture();
    const Viewport view = lab.sceneViewport();
    CHECK(view.x > 0);  // the sidebar's width
    CHECK(view.x < image.width / 2);
    CHECK(view.x + view.width == image.width);
    checkCornellImage(image, lab.camera(), view);
}

TEST_CASE("an offscreen capture matches the Cornell layout at a size unlike the window's") {
    requireDisplay();
    LabOptions options;
    options.maxPatchArea = 0.01;  // coarse: quick to mesh and solve
    options.width = 640;
    options.height = 400;
    options.showPanels = false;
    Lab lab(options);
    // The layout check reads material colours: show reflectance, not the (still dark) solution.
    lab.display().colourMode = radiant::render::ColourMode::Reflectance;
    lab.display().highlightShooter = false;  // the default method shoots: its shooter's outline is orange
    waitForMesh(lab);
    lab.frame();
    const ImageRgb8 image = lab.renderOffscreen(500, 360);
    REQUIRE(image.width == 500);
    REQUIRE(image.height == 360);
    checkCornellImage(image, lab.camera(), Viewport{0, 0, 500, 360});
}

}  // TEST_SUITE
