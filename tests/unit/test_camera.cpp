// Camera math the window and the GL tests share (GL-free): the Cornell camera's field of view from
// its lens and film, aspect handling, and the orbit camera's gestures.
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <utility>

#include "app/ui/FrameStats.h"
#include "render/camera/Camera.h"
#include "render/camera/OrbitCamera.h"

using namespace radiant;
using render::Camera;
using render::OrbitCamera;
using render::Viewport;

TEST_SUITE("camera") {

TEST_CASE("the Cornell camera's field spans the 25 mm film behind a 35 mm lens") {
    const Camera camera = render::cornellCamera();
    const double halfFilm = 12.5, focal = 35.0;
    CHECK(camera.fieldOfView.value() == doctest::Approx(2.0 * std::atan(halfFilm / focal)));
    for (const Viewport view : {Viewport{0, 0, 1000, 1000}, Viewport{0, 0, 1600, 1000}, Viewport{300, 0, 1300, 1000}}) {
        CAPTURE(view.width);
        // A point at the film's top edge, anywhere along the line of sight, lands on the top row.
        for (const double depth : {0.5, 1.0, 3.0}) {
            const glm::dvec3 top = camera.eye + glm::dvec3(0, depth * halfFilm / focal, depth);
            const glm::dvec3 p = render::projectToPixel(camera, view, top);
            CHECK(p.y == doctest::Approx(0.0).epsilon(1e-9));
            CHECK(p.x == doctest::Approx(view.x + view.width / 2.0));
        }
        // +x lies on the image's left when looking along +z with +y up.
        CHECK(render::projectToPixel(camera, view, camera.eye + glm::dvec3(0.1, 0, 1)).x < view.x + view.width / 2.0);
    }
}

TEST_CASE("a portrait view keeps the field horizontally, so the framed box still fits") {
    const Camera camera = render::cornellCamera();
    const Viewport portrait{0, 0, 500, 1000};
    const double halfFilm = 12.5, focal = 35.0;
    const glm::dvec3 leftEdge = camera.eye + glm::dvec3(halfFilm / focal, 0, 1);  // +x is left
    CHECK(render::projectToPixel(camera, portrait, leftEdge).x == doctest::Approx(0.0).epsilon(1e-9));
}

TEST_CASE("orbiting keeps the distance to the pivot, and reset returns the home view exactly") {
    const Camera home = render::cornellCamera();
    const glm::dvec3 centre{0.278, 0.2744, 0.2796};
    OrbitCamera orbit(home, centre);
    // The pivot is the point on the home line of sight nearest the centre.
    CHECK(orbit.pivot().x == doctest::Approx(0.278));
    CHECK(orbit.pivot().y == doctest::Approx(0.273));
    CHECK(orbit.pivot().z == doctest::Approx(0.2796));
    CHECK(orbit.distance() == doctest::Approx(0.2796 + 0.8));
    CHECK(glm::length(orbit.camera().eye - home.eye) < 1e-12);

    orbit.orbit(Radians(std::numbers::pi / 2), Radians(0.0));
    // A quarter turn of yaw looks along +x from the pivot's -x side.
    CHECK(orbit.camera().forward.x == doctest::Approx(1.0));
    CHECK(orbit.camera().eye.x == doctest::Approx(0.278 - orbit.distance()));
    for (const double pitch : {0.3, -0.7, 5.0}) {
        orbit.orbit(Radians(0.4), Radians(pitch));
        CHECK(glm::length(orbit.camera().eye - orbit.pivot()) == doctest::Approx(orbit.distance()));
        CHECK(std::abs(orbit.camera().forward.y) < std::sin(89.5 * std::numbers::pi / 180));  // never at a pole
    }
    orbit.zoom(2.0);
    CHECK(orbit.distance() == doctest::Approx((0.2796 + 0.8) * 0.85 * 0.85));
    orbit.pan(0.2, 0.1);
    orbit.reset();
    CHECK(glm::length(orbit.camera().eye - home.eye) < 1e-12);
    CHECK(glm::length(orbit.camera().forward - home.forward) < 1e-12);
}

TEST_CASE("panning keeps the dragged point under the cursor") {
    const Viewport view{0, 0, 1200, 800};
    for (const auto& [dx, dy] : {std::pair{120.0, 0.0}, std::pair{-40.0, 75.0}, std::pair{300.0, -200.0}}) {
        OrbitCamera orbit(render::cornellCamera(), {0.278, 0.2744, 0.2796});
        const glm::dvec3 grabbed = orbit.pivot();
        const glm::dvec3 before = render::projectToPixel(orbit.camera(), view, grabbed);
        orbit.pan(dx / view.height, -dy / view.height);  // what CameraController does for a drag of (dx, dy)
        const glm::dvec3 after = render::projectToPixel(orbit.camera(), view, grabbed);
        CHECK(after.x - before.x == doctest::Approx(dx));
        CHECK(after.y - before.y == doctest::Approx(dy));
    }
}

TEST_CASE("the framing camera shows every corner of a scene's bounds") {
    const Viewport view{0, 0, 1600, 1000};
    for (const auto& [lo, hi] : {std::pair{glm::dvec3(0), glm::dvec3(1)}, std::pair{glm::dvec3(-5, 0, -2), glm::dvec3(5, 0.1, 2)},
                                 std::pair{glm::dvec3(10, 10, 10), glm::dvec3(10.01, 10.3, 10.02)}}) {
        const Camera camera = render::framingCamera(lo, hi);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
            const glm::dvec3 pixel = render::projectToPixel(camera, view, p);
            CHECK(pixel.x >= 0);
            CHECK(pixel.x <= view.width);
            CHECK(pixel.y >= 0);
            CHECK(pixel.y <= view.height);
            CHECK(pixel.z > 0);
            CHECK(pixel.z < 1);
        }
    }
}

TEST_CASE("frame time readout is the median of the last frames") {
    app::FrameStats stats(5);
    CHECK(stats.medianSeconds() == 0.0);
    for (const double t : {0.010, 0.030, 0.020}) stats.add(t);
    CHECK(stats.medianSeconds() == doctest::Approx(0.020));
    stats.add(0.500);  // one hitch: the median moves to between 0.020 and 0.030
    CHECK(stats.medianSeconds() == doctest::Approx(0.025));
    for (int i = 0; i < 5; ++i) stats.add(0.016);  // the window forgets older frames
    CHECK(stats.count() == 5);
    CHECK(stats.medianSeconds() == doctest::Approx(0.016));
}

}  // TEST_SUITE
