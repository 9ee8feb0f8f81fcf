// Picking what the 3D view shows: the view draws faces from their fronts only, so a click passes
// through a face met from behind (a closed room's near wall seen from outside) to the first front
// face beyond. Checked on the closed room of tests/data/gltf against its hand-written geometry.
#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/SceneLibrary.h"

using namespace radiant;

TEST_CASE("front picking: a ray from outside a closed room passes the near wall's back and lands on the floor") {
    const Scene room = loadScene(RADIANT_TEST_DATA_DIR "/gltf/closed_room.gltf").scene;
    const RayCaster rays(room);
    // From above the ceiling (y = 2.5) straight down onto the floor's centre.
    const glm::dvec3 eye{2.5, 4.0, 2.0}, down{0, -1, 0};
    const auto any = rays.intersect(eye, down);
    REQUIRE(any);
    CHECK(room.surfaces[any->surface].name == "ceiling");  // its back: it faces down, into the room
    CHECK(any->distance == doctest::Approx(1.5).epsilon(1e-9).scale(0));
    const auto front = rays.intersectFront(eye, down);
    REQUIRE(front);
    CHECK(room.surfaces[front->surface].name == "floor");
    CHECK(front->distance == doctest::Approx(4.0).epsilon(1e-9).scale(0));
    CHECK(glm::dot(front->normal, down) < 0);
    // From inside, the first face met is a front already: both agree.
    const auto inside = rays.intersectFront({2.0, 1.0, 1.5}, {0, 0, 1});
    REQUIRE(inside);
    CHECK(room.surfaces[inside->surface].name == "wall south");
    CHECK(inside->distance == doctest::Approx(1.5).epsilon(1e-9).scale(0));
    // Up from under the lamp, whose front faces down into the room: the lamp, 1 cm below the ceiling.
    const auto up = rays.intersectFront({2.0, 1.0, 1.5}, {0, 1, 0});
    REQUIRE(up);
    CHECK(room.surfaces[up->surface].name == "ceiling lamp");
    CHECK(up->distance == doctest::Approx(1.49).epsilon(1e-6).scale(0));
    // From below the room looking up: through the floor's back to the lamp's front.
    const auto fromBelow = rays.intersectFront({2.0, -1.0, 1.5}, {0, 1, 0});
    REQUIRE(fromBelow);
    CHECK(room.surfaces[fromBelow->surface].name == "ceiling lamp");
    // Looking away from the room: nothing to pick.
    CHECK_FALSE(rays.intersectFront({2.0, -1.0, 1.5}, {0, -1, 0}).has_value());
}
