// A closed room (tests/data/gltf/closed_room.gltf: 4 x 3 m, 2.5 m high, a ceiling lamp, a cabinet)
// in the real lab: it opens showing its interior from its home camera, the floor's own colour is on
// screen where the floor's centre projects, and a click there probes the floor from above. Faces
// are drawn from their fronts only, so no wall seen from behind hides the room.
#include <doctest/doctest.h>

#include <cstdlib>
#include <functional>
#include <glm/geometric.hpp>
#include <string>

#include "app/Lab.h"
#include "radiometry/geometry/RayCaster.h"
#include "app/solver/SolverThread.h"
#include "app/window/PickRay.h"
#include "app/window/Window.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/scene/View.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using radiant::app::Lab;
using radiant::app::LabOptions;
namespace command = radiant::app::command;

using radiant::test::frameUntil;
using radiant::test::requireDisplay;

namespace {

/// Mean colour (0..255 per channel) of a (2r+1)^2 block of pixels around `centre`.
glm::dvec3 meanColourAround(const render::ImageRgb8& image, const glm::dvec3& centre, int r = 3) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = static_cast<int>(centre.y) - r; y <= static_cast<int>(centre.y) + r; ++y)
        for (int x = static_cast<int>(centre.x) - r; x <= static_cast<int>(centre.x) + r; ++x) {
            sum += glm::dvec3(image.at(x, y));
            ++count;
        }
    return sum / static_cast<double>(count);
}

} // namespace

TEST_SUITE("gl lab") {

TEST_CASE("a closed room opens showing its floor from the home camera, and a click inside probes the floor") {
    requireDisplay();
    LabOptions options;
    options.scene = RADIANT_TEST_DATA_DIR "/gltf/closed_room.gltf";
    options.width = 640;
    options.height = 480;
    options.showPanels = false;
    options.vsync = false;
    options.maxPatchArea = 0.25;
    options.runOnStart = false;
    const std::uint64_t castersBefore = RayCaster::constructed();
    Lab lab(options);
    frameUntil(lab, [](const app::Snapshot& s) { return s.mesh && s.solverBuilds >= 1 && !s.running; });
    lab.send(command::Run{});
    frameUntil(lab, [](const app::Snapshot& s) { return !s.running && s.stats.iteration > 0; });

    // The home camera stands inside (a wide view from near one wall) or outside with the near walls
    // culled; either way the floor is in view: the ray through the view's lower middle lands on it,
    // inside the room and clear of the cabinet (x 0.4-1.2, z 0.3-0.8).
    const render::Viewport viewport = lab.sceneViewport();
    const glm::dvec2 pixel{viewport.x + viewport.width / 2.0, viewport.y + 0.8 * viewport.height};
    const app::PickRay ray = app::pickRay(lab.camera(), viewport, pixel);
    REQUIRE(ray.direction.y < 0);
    const glm::dvec3 floorPoint = ray.origin - ray.origin.y / ray.direction.y * ray.direction;
    INFO("the view's lower middle looks at (" << floorPoint.x << ", " << floorPoint.y << ", " << floorPoint.z << ")");
    REQUIRE(floorPoint.x > 1.3);
    REQUIRE(floorPoint.x < 3.9);
    REQUIRE(floorPoint.z > 0.9);
    REQUIRE(floorPoint.z < 2.9);
    const render::ImageRgb8 image = lab.frameAndCapture();
    // Oak (reflectance 0.55, 0.35, 0.2) under a near-white lamp: red over green over blue, where the
    // plaster walls (0.7 grey) and the blue cabinet would show grey or blue.
    const glm::dvec3 floor = meanColourAround(image, glm::dvec3(pixel, 0.0));
    INFO("floor pixel (" << floor.x << ", " << floor.y << ", " << floor.z << ")");
    CHECK(floor.x > floor.y + 15);
    CHECK(floor.y > floor.z + 10);
    CHECK(floor.x > 60);  // lit, not the background

    // A click there probes the floor from above: a reading with the floor's light.
    REQUIRE(lab.clickAt({pixel.x, pixel.y}));
    const std::uint64_t solved = lab.snapshot()->generation;
    frameUntil(lab, [&](const app::Snapshot&) { return lab.probeGeneration() == solved && lab.probeReading(); });
    const ProbeReading reading = *lab.probeReading();
    CHECK(lab.snapshot()->scene->surfaces[reading.at.surface].name == "floor");
    CHECK(reading.normal.y == doctest::Approx(1.0).scale(0));
    CHECK(glm::distance(reading.at.point, floorPoint) < 1e-3);
    CHECK(reading.radiosity.value().x > 0.0);
    CHECK(reading.irradiance.value().x > reading.radiosity.value().x);  // B = rho E with rho 0.55
    // One BVH for the room: the solver thread's, which the home view's inside-or-outside choice, the
    // solver, the pick and the probe all cast with.
    CHECK(RayCaster::constructed() - castersBefore == 1);
}

TEST_CASE("seen from outside, a closed room's near walls are culled like a cut-away, and the floor shows through") {
    requireDisplay();
    const Scene room = loadScene(RADIANT_TEST_DATA_DIR "/gltf/closed_room.gltf").scene;
    const PatchMesh mesh = meshScene(room, {0.25});
    glm::dvec3 lo, hi;
    REQUIRE(sceneBounds(room, lo, hi));
    // Three-quarters from above and outside: every ray to the floor crosses the ceiling's or a
    // wall's back.
    const render::Camera outside = render::cameraFromView(framingView(lo, hi));
    constexpr int kSize = 320;
    const glm::dvec3 floorPoint{2.6, 0.0, 1.8};
    const glm::dvec3 pixel = render::projectToPixel(outside, {0, 0, kSize, kSize}, floorPoint);
    REQUIRE(pixel.x > 4);
    REQUIRE(pixel.x < kSize - 4);
    REQUIRE(pixel.y > 4);
    REQUIRE(pixel.y < kSize - 4);

    const app::Window window({64, 64, "closed room test", false, false});
    auto renderer = std::make_unique<render::PatchRenderer>();
    renderer->setMesh(room, mesh, 1);
    render::DisplaySettings settings;
    settings.colourMode = render::ColourMode::Reflectance;
    renderer->setSettings(settings);
    renderer->prepare();
    const render::ImageRgb8 image = render::renderOffscreen(*renderer, outside, kSize, kSize, {0, 0, 0});
    renderer.reset();  // GL objects die while the context lives
    // Oak's reflectance (0.55, 0.35, 0.2), dimmed by the unlit view's shading: red over green over
    // blue; the plaster ceiling or walls, had they hidden it, are grey.
    const glm::dvec3 floor = meanColourAround(image, pixel);
    INFO("floor pixel (" << floor.x << ", " << floor.y << ", " << floor.z << ")");
    CHECK(floor.x > floor.y + 20);
    CHECK(floor.y > floor.z + 15);
}

}  // TEST_SUITE
