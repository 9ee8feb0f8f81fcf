// The lecture demos' 3D pictures (GL-free, as the lab builds them each frame) hold the physics they
// show: the square's projected patch has the square's solid angle for its area, a regular solid's
// highlighted face subtends 4 pi / n, the false-colour plane follows I cos theta / r^2, the emitter
// reads the same L from every probe, the beam cross-section is cos theta. And a demo puts the
// scene's camera aside and gives it back.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/panels/demos/DemoView.h"
#include "app/panels/demos/LectureDemos.h"
#include "tests/support/Relative.h"

using namespace radiant;
using radiant::test::relativeTo;
namespace colour = render::demo_colour;

namespace {

bool same(const glm::vec4& a, const glm::vec4& b) { return glm::length(a - b) < 1e-6f; }

/// Area of the triangles drawn in `colour` (m^2).
double areaIn(const render::DemoDrawing& d, const glm::vec4& colour) {
    double area = 0;
    for (std::size_t i = 0; i + 2 < d.triangles.size(); i += 3)
        if (same(d.triangles[i].colour, colour)) {
            const glm::dvec3 a(d.triangles[i].position), b(d.triangles[i + 1].position), c(d.triangles[i + 2].position);
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    return area;
}

/// Van Oosterom & Strackee (1983): the solid angle of triangle abc seen from the origin.
double triangleSolidAngle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2 * std::atan2(numerator, denominator);
}

/// The number after `key` in the first label holding it.
double numberAfter(const render::DemoDrawing& d, const std::string& key) {
    for (const render::DemoLabel& label : d.labels)
        if (const std::size_t at = label.text.find(key); at != std::string::npos)
            return std::stod(label.text.substr(at + key.size()));
    FAIL("no label holds '" << key << "'");
    return 0;
}

} // namespace

TEST_CASE("the square's projection onto the unit hemisphere has the square's solid angle for its area") {
    for (const std::pair<double, double>& sideAndDistance : {std::pair{1.0, 2.0}, std::pair{0.5, 0.3}, std::pair{3.0, 1.0}}) {
        const double side = sideAndDistance.first, distance = sideAndDistance.second;
        CAPTURE(side);
        CAPTURE(distance);
        app::SquareSolidAngleDemo demo;
        demo.settings = {side, distance};
        const double a = side / 2;
        // Four corner rectangles: 4 atan(a^2 / (R sqrt(2 a^2 + R^2))) (docs/reference.md).
        const double closedForm = 4 * std::atan(a * a / (distance * std::sqrt(2 * a * a + distance * distance)));
        // Flat triangles under a curved patch: 24 x 24 cells fall short by well under 0.5%.
        CHECK(areaIn(demo.picture(std::nullopt), colour::kHighlight) == relativeTo(closedForm, 5e-3));
    }
}

TEST_CASE("a regular solid's highlighted face subtends 4 pi / n, and its faces the whole sphere") {
    for (int choice = 0; choice < 5; ++choice) {
        app::DodecahedronDemo demo;
        demo.faceChoice = choice;
        const int faces = std::array{4, 6, 8, 12, 20}[static_cast<std::size_t>(choice)];
        CAPTURE(faces);
        const render::DemoDrawing d = demo.picture(std::nullopt);
        double highlighted = 0, all = 0;
        int highlightedTriangles = 0;
        for (std::size_t i = 0; i + 2 < d.triangles.size(); i += 3) {
            const double omega = triangleSolidAngle(glm::dvec3(d.triangles[i].position), glm::dvec3(d.triangles[i + 1].position),
                                                    glm::dvec3(d.triangles[i + 2].position));
            if (glm::length(d.triangles[i].position) > 0.9f) all += omega;  // the solid's faces (vertices on the unit sphere)
            if (same(d.triangles[i].colour, colour::kHighlight)) {
                highlighted += omega;
                ++highlightedTriangles;
            }
        }
        CHECK(highlightedTriangles > 0);
        CHECK(highlighted == relativeTo(4 * std::numbers::pi / faces, 1e-5));
        CHECK(all == relativeTo(4 * std::numbers::pi, 1e-5));
    }
}

TEST_CASE("the point-source plane is coloured by E = I cos theta / r^2, and the cursor reads it out") {
    app::PointSourceDemo demo;
    demo.settings = {100, 1.5, 1.0};
    const render::DemoDrawing d = demo.picture(std::nullopt);
    const double intensity = 100 / (4 * std::numbers::pi);
    const auto closedForm = [&](const glm::dvec3& p) {
        const glm::dvec3 toSource = glm::dvec3(1.0, 1.5, 0.0) - p;
        const double r = glm::length(toSource);
        return intensity * (toSource.y / r) / (r * r);
    };
    // The contour coordinate is E over the isoline step: one ratio across the whole plane.
    std::vector<double> ratios;
    glm::dvec3 brightest(0.0);
    float best = -1;
    for (const render::DemoVertex& v : d.triangles)
        if (v.position.y == 0.0f && v.contour >= 0 && std::abs(v.position.x) <= 5.0f) {
            ratios.push_back(v.contour / closedForm(glm::dvec3(v.position)));
            if (v.contour > best) {
                best = v.contour;
                brightest = glm::dvec3(v.position);
            }
        }
    REQUIRE(ratios.size() > 1000);
    for (const double r : ratios) CHECK(r == relativeTo(ratios.front(), 1e-4));
    CHECK(std::abs(brightest.x - 1.0) < 0.11);  // the brightest vertex is under the source
    CHECK(std::abs(brightest.z) < 0.11);

    // The pointer's ray straight down onto (2, 0, -1).
    const render::DemoDrawing pointed = demo.picture(app::PickRay{{2.0, 5.0, -1.0}, {0.0, -1.0, 0.0}});
    CHECK(numberAfter(pointed, "cursor: E = ") == relativeTo(closedForm({2.0, 0.0, -1.0}), 1e-3));
}

TEST_CASE("the diffuse emitter reads the same radiance from every probe, and its area is A") {
    app::DiffuseEmitterDemo demo;
    demo.settings = {250, 2.0};
    const render::DemoDrawing d = demo.picture(std::nullopt);
    int probes = 0;
    for (const render::DemoLabel& label : d.labels)
        if (const std::size_t at = label.text.find("L = I / (A cos theta) = "); at != std::string::npos) {
            CHECK(std::stod(label.text.substr(at + 24)) == relativeTo(250, 1e-3));
            ++probes;
        }
    CHECK(probes == 3);
    double emitterArea = 0;
    for (std::size_t i = 0; i + 2 < d.triangles.size(); i += 3)
        if (d.triangles[i].position.y == 0 && d.triangles[i + 1].position.y == 0 && d.triangles[i + 2].position.y == 0) {
            const glm::dvec3 a(d.triangles[i].position), b(d.triangles[i + 1].position), c(d.triangles[i + 2].position);
            emitterArea += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    CHECK(emitterArea == relativeTo(2.0, 1e-5));
    CHECK(numberAfter(d, "P = pi L A = ") == relativeTo(std::numbers::pi * 250 * 2, 1e-4));
}

TEST_CASE("the tilted receiver intercepts a beam cross-section of cos theta, and E = L omega cos theta") {
    for (const double tilt : {0.0, 30.0, 60.0, 85.0}) {
        CAPTURE(tilt);
        app::RadianceIrradianceDemo demo;
        demo.settings = {1000, 1e-3, tilt};
        const render::DemoDrawing d = demo.picture(std::nullopt);
        glm::vec4 veil = colour::kHighlight;
        veil.w = 0.25f;
        const double c = std::cos(tilt * std::numbers::pi / 180);
        CHECK(areaIn(d, veil) == relativeTo(c, 1e-5));
        CHECK(numberAfter(d, "E = L omega cos theta = ") == relativeTo(1000 * 1e-3 * c, 1e-3));
    }
}

TEST_CASE("the Sun demo shows the same L at every planet and E = L omega") {
    app::SunDemo demo;
    demo.distanceAu = 5.2;  // Jupiter
    const render::DemoDrawing d = demo.picture(std::nullopt);
    int planets = 0;
    for (const render::DemoLabel& label : d.labels) {
        const std::size_t omegaAt = label.text.find("omega = "), eAt = label.text.find("E = L omega = ");
        if (omegaAt == std::string::npos || eAt == std::string::npos) continue;
        ++planets;
        // 2 pi (1 - cos alpha), sin alpha = R / d, with the lecture's Sun (R = sqrt(A / 4 pi)).
        const double au = std::stod(label.text.substr(label.text.find(", ") + 2));
        const double radius = std::sqrt(6.07e18 / (4 * std::numbers::pi)), distance = au * 1.496e11;
        const double omega = 2 * std::numbers::pi * (1 - std::sqrt(1 - radius * radius / (distance * distance)));
        const double radiance = 3.91e26 / (std::numbers::pi * 6.07e18);
        CHECK(std::stod(label.text.substr(omegaAt + 8)) == relativeTo(omega, 2e-3));
        CHECK(std::stod(label.text.substr(eAt + 14)) == relativeTo(radiance * omega, 2e-3));
    }
    CHECK(planets == 3);
}

TEST_CASE("a demo puts the scene's camera aside and gives it back, however many demos open in between") {
    render::Camera home;
    home.eye = {1, 2, 3};
    home.forward = glm::normalize(glm::dvec3(-1, -2, -3));
    render::OrbitCamera orbit(home, {0, 0, 0});
    orbit.orbit(Radians(0.3), Radians(0.1));  // the user moved it
    const render::Camera moved = orbit.camera();
    app::DemoView view(orbit);
    app::SunDemo sun;
    app::DodecahedronDemo dodecahedron;
    view.open(sun);
    CHECK(view.active() == &sun);
    CHECK(glm::length(orbit.camera().eye - sun.framing().camera.eye) < 1e-9);
    CHECK(glm::length(view.sceneCamera().camera().eye - moved.eye) < 1e-12);
    view.open(dodecahedron);
    CHECK(view.active() == &dodecahedron);
    view.close();
    CHECK(view.active() == nullptr);
    CHECK(glm::length(orbit.camera().eye - moved.eye) < 1e-12);
    CHECK(glm::length(orbit.camera().forward - moved.forward) < 1e-12);
    view.close();  // nothing open: nothing changes
    CHECK(glm::length(orbit.camera().eye - moved.eye) < 1e-12);
}

TEST_CASE("a demo framed wider than the view shows its framed width through a wider field") {
    render::Camera framed;
    framed.fieldOfView = Radians(50 * std::numbers::pi / 180);
    const double framedHalfWidth = std::tan(0.5 * framed.fieldOfView.value()) * 1.6;  // at unit distance
    // A lesson's wide view keeps the demo's field; a tall one (no caption) widens it to the same width.
    CHECK(app::showingFramedWidth(framed, 1.8, 1.6).fieldOfView.value() == framed.fieldOfView.value());
    for (const double aspect : {1.16, 1.4}) {
        CAPTURE(aspect);
        const render::Camera shown = app::showingFramedWidth(framed, aspect, 1.6);
        CHECK(shown.verticalFieldOfView(aspect).value() > framed.fieldOfView.value());
        CHECK(std::tan(0.5 * shown.verticalFieldOfView(aspect).value()) * aspect == relativeTo(framedHalfWidth, 1e-12));
    }
    // Portrait: the camera's field is its horizontal one, widened to the framed width.
    const render::Camera portrait = app::showingFramedWidth(framed, 0.7, 1.6);
    CHECK(std::tan(0.5 * portrait.fieldOfView.value()) == relativeTo(framedHalfWidth, 1e-12));
    // A demo framed for no particular width (0) keeps its field in any view.
    CHECK(app::showingFramedWidth(framed, 0.7, 0).fieldOfView.value() == framed.fieldOfView.value());
}
