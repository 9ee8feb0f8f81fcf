// A two-sided face is two coincident surfaces (Surface::side), one radiosity per side. The depth
// test alone cannot tell them apart (whichever is drawn first wins from both sides, and a room made
// of Blender's outward-facing cube looked black from inside): each view must show the side facing it.
#include <doctest/doctest.h>

#include <cstdlib>
#include <memory>
#include <vector>

#include "app/window/Window.h"
#include "radiometry/mesh/PatchMesh.h"
#include "render/OffscreenRender.h"
#include "render/PatchRenderer.h"

using namespace radiant;

namespace {

constexpr int kSize = 64;
const glm::vec3 kBackground{0, 0, 1};  // blue: no surface drawn

/// The unit square in z = 0 as a front (+z) and its reversed back (-z), grey, one patch each.
Scene twoSidedSquare(FaceSide front = FaceSide::Front, FaceSide back = FaceSide::Back) {
    Scene scene;
    scene.name = "two-sided square";
    scene.materials.push_back({"grey", Rgb(0.5), ExitanceRgb{}});
    Face up{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 1.0};
    Face down{{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {0, 0, -1}, 1.0};
    scene.surfaces.push_back({"square", 0, {up}, "test", front});
    scene.surfaces.push_back({"square (back)", 0, {down}, "test", back});
    return scene;
}

render::Camera looking(double z) {
    render::Camera camera;
    camera.eye = {0.5, 0.5, z};
    camera.forward = {0, 0, z > 0 ? -1 : 1};
    camera.up = {0, 1, 0};
    return camera;
}

/// The centre pixel's red channel seen from +z and from -z, with radiosity `front` and `back`.
std::pair<int, int> centreFromBothSides(const Scene& scene, double front, double back) {
    const app::Window window({64, 64, "two-sided test", false, false});
    auto renderer = std::make_unique<render::PatchRenderer>();
    const PatchMesh mesh = meshScene(scene, MeshingOptions{1.0});
    REQUIRE(mesh.size() == 2);
    renderer->setMesh(scene, mesh, 1);
    renderer->setRadiosity(std::vector<Rgb>{Rgb(front), Rgb(back)}, 1, -1);
    render::DisplaySettings settings;
    settings.highlightShooter = false;
    settings.exposureKey = render::ExposureKey::Automatic;  // keyed on the lit side: it shows mid-grey
    renderer->setSettings(settings);
    renderer->prepare();
    const render::ImageRgb8 above = render::renderOffscreen(*renderer, looking(1.5), kSize, kSize, kBackground);
    const render::ImageRgb8 below = render::renderOffscreen(*renderer, looking(-1.5), kSize, kSize, kBackground);
    CHECK(above.at(kSize / 2, kSize / 2).z < 200);  // a surface, not the backdrop
    CHECK(below.at(kSize / 2, kSize / 2).z < 200);
    const std::pair<int, int> centre{above.at(kSize / 2, kSize / 2).x, below.at(kSize / 2, kSize / 2).x};
    renderer.reset();  // GL objects die while the context lives
    return centre;
}

} // namespace

TEST_SUITE("gl display") {

TEST_CASE("each side of a two-sided face shows its own radiosity, whichever is drawn first") {
    const char* display = std::getenv("DISPLAY");
    REQUIRE_MESSAGE((display != nullptr && *display != '\0'), "the GL tests need an X server (xvfb-run)");
    // Lit front, dark back; then the other way round, so draw order cannot pass the test.
    const auto [frontLitAbove, frontLitBelow] = centreFromBothSides(twoSidedSquare(), 10.0, 0.0);
    CHECK(frontLitAbove > 100);
    CHECK(frontLitBelow < 10);
    const auto [backLitAbove, backLitBelow] = centreFromBothSides(twoSidedSquare(), 0.0, 10.0);
    CHECK(backLitAbove < 10);
    CHECK(backLitBelow > 100);
}

} // TEST_SUITE
