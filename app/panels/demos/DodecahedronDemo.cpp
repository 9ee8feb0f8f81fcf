// The lecture's "one steradian": a dodecahedron's 12 faces share the sphere's 4 pi sr, 1.047 sr each.
// Shown two ways: 4 pi / n, and one face's solid angle from its vertices (Van Oosterom & Strackee),
// with the face of a regular solid built from its known vertex coordinates.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "app/panels/demos/DemoText.h"
#include "app/panels/demos/LectureDemos.h"
#include "app/ui/WrappedText.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"
#include "radiometry/solidangle/PolygonSolidAngle.h"

namespace radiant::app {
namespace {

constexpr std::array<int, 5> kFaceCounts{4, 6, 8, 12, 20};

/// One face of each regular solid centred on the origin (any scale: solid angles are scale-free).
std::vector<glm::dvec3> oneFace(int faces) {
    const double phi = std::numbers::phi;
    switch (faces) {
    case 4: return {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}};
    case 6: return {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
    case 8: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case 12:  // the pentagon around the face centre direction (0, 1, phi) ... vertices of the standard dodecahedron
        return {{0, 1 / phi, phi}, {1, 1, 1}, {phi, 0, 1 / phi}, {1, -1, 1}, {0, -1 / phi, phi}};
    case 20: return {{0, 1, phi}, {0, -1, phi}, {phi, 0, 1}};
    default: return {};
    }
}

/// {+-x, +-y, +-z} for each point, without repeats.
std::vector<glm::dvec3> allSigns(std::initializer_list<glm::dvec3> points) {
    std::vector<glm::dvec3> v;
    for (const glm::dvec3& p : points)
        for (int mask = 0; mask < 8; ++mask) {
            const glm::dvec3 q{(mask & 1) ? -p.x : p.x, (mask & 2) ? -p.y : p.y, (mask & 4) ? -p.z : p.z};
            if (std::find(v.begin(), v.end(), q) == v.end()) v.push_back(q);
        }
    return v;
}

/// The vertices of each regular solid about the origin, in the orientation oneFace() takes its face from.
std::vector<glm::dvec3> solidVertices(int faces) {
    const double phi = std::numbers::phi, iphi = 1 / phi;
    switch (faces) {
    case 4: return {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    case 6: return allSigns({{1, 1, 1}});
    case 8: return allSigns({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    case 12: return allSigns({{1, 1, 1}, {0, iphi, phi}, {iphi, phi, 0}, {phi, 0, iphi}});
    case 20: return allSigns({{0, 1, phi}, {1, phi, 0}, {phi, 0, 1}});
    default: return {};
    }
}

/// The directions of each solid's face centres: the vertices of its dual, turned to match (a face is
/// then the vertices farthest along one of them; tests/unit/test_demo_pictures.cpp checks that every
/// face subtends 4 pi / n).
std::vector<glm::dvec3> faceDirections(int faces) {
    const double phi = std::numbers::phi, iphi = 1 / phi;
    std::vector<glm::dvec3> directions;
    switch (faces) {
    case 4: directions = {{-1, -1, -1}, {-1, 1, 1}, {1, -1, 1}, {1, 1, -1}}; break;
    case 6: directions = allSigns({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}); break;
    case 8: directions = allSigns({{1, 1, 1}}); break;
    case 12: directions = allSigns({{0, phi, 1}, {phi, 1, 0}, {1, 0, phi}}); break;
    case 20: directions = allSigns({{1, 1, 1}, {0, phi, iphi}, {phi, iphi, 0}, {iphi, 0, phi}}); break;
    default: break;
    }
    for (glm::dvec3& d : directions) d = glm::normalize(d);
    return directions;
}

/// The face around `direction`: the vertices farthest along it, in order around it, on the unit sphere.
std::vector<glm::dvec3> faceAround(const std::vector<glm::dvec3>& vertices, const glm::dvec3& direction) {
    double farthest = -1e9;
    for (const glm::dvec3& v : vertices) farthest = std::max(farthest, glm::dot(glm::normalize(v), direction));
    std::vector<glm::dvec3> face;
    for (const glm::dvec3& v : vertices)
        if (glm::dot(glm::normalize(v), direction) > farthest - 1e-9) face.push_back(glm::normalize(v));
    const glm::dvec3 u = glm::normalize(face[0] - direction * glm::dot(face[0], direction)), w = glm::cross(direction, u);
    std::sort(face.begin(), face.end(), [&](const glm::dvec3& a, const glm::dvec3& b) {
        return std::atan2(glm::dot(a, w), glm::dot(a, u)) < std::atan2(glm::dot(b, w), glm::dot(b, u));
    });
    return face;
}

/// The face the picture singles out: the one nearest this direction, off to the side of the view.
const glm::dvec3 kHighlightToward = glm::normalize(glm::dvec3(1.0, 0.35, 0.25));

} // namespace

RegularSolidNumbers regularSolidNumbers(int faces) {
    RegularSolidNumbers n;
    n.faces = faces;
    n.perFace = regularSolidFaceSolidAngle(faces);
    const std::vector<glm::dvec3> face = oneFace(faces);
    n.polygonRoute = polygonSolidAngle({0, 0, 0}, face);
    return n;
}

DemoFraming DodecahedronDemo::framing() const { return framingFrom({2.35, 1.6, -3.05}, {0.2, 0.2, 0.0}, 50); }

// The chosen solid around the eye at its centre (vertices on the unit sphere), its faces veiled and
// one face, the one nearest kHighlightToward, solid with the rays from the eye to its corners and its
// solid angle from its corners beside 4 pi / n.
render::DemoDrawing DodecahedronDemo::picture(const std::optional<PickRay>&) const {
    using namespace render::demo_colour;
    const int faces = kFaceCounts[static_cast<std::size_t>(faceChoice)];
    const RegularSolidNumbers n = regularSolidNumbers(faces);
    const std::vector<glm::dvec3> vertices = solidVertices(faces);
    std::vector<glm::dvec3> directions = faceDirections(faces);
    const auto nearest = std::max_element(directions.begin(), directions.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
        return glm::dot(a, kHighlightToward) < glm::dot(b, kHighlightToward);
    });
    render::DemoDrawing d;
    const auto p = [](const glm::dvec3& v) { return point3(v.x, v.y, v.z); };
    std::vector<glm::dvec3> highlighted;
    for (auto it = directions.begin(); it != directions.end(); ++it) {
        const std::vector<glm::dvec3> face = faceAround(vertices, *it);
        const bool chosen = it == nearest;
        if (chosen) highlighted = face;
        glm::vec4 fill = chosen ? kHighlight : kSurface;
        fill.w = chosen ? 1.0f : 0.16f;
        for (std::size_t k = 1; k + 1 < face.size(); ++k) d.triangle({p(face[0]), fill}, {p(face[k]), fill}, {p(face[k + 1]), fill});
        std::vector<glm::vec3> outline;
        for (const glm::dvec3& v : face) outline.push_back(p(v));
        d.loop(outline, chosen ? kText : kAxis, chosen ? 3.0f : 1.5f);
    }
    d.sphere({0, 0, 0}, 0.05f, kProbe, 10);
    d.label(point3(-0.1, -0.2, 0), "eye", kProbe);
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : highlighted) {
        d.line({0, 0, 0}, p(v), kProbe, 2.0f);
        centre += v / static_cast<double>(highlighted.size());
    }
    // Above the solid, a leader line from the face's centre, so the label leaves the face to be seen.
    const glm::vec3 labelAt = p(centre * 1.15) + glm::vec3(0.0f, 0.75f, 0.0f);
    d.line(p(centre), labelAt, kHighlight, 1.5f);
    d.label(labelAt,
            printed("one face of %d: 4 pi / %d = %.4f sr\nfrom its corners: %.4f sr", faces, faces, n.perFace.value(),
                    n.polygonRoute.value()), kHighlight);
    return d;
}

void DodecahedronDemo::draw() {
    // Wide enough for the longest choice and the arrow button at any UI scale.
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("12 (dodeca)").x + ImGui::GetStyle().FramePadding.x * 2 +
                            ImGui::GetFrameHeight());
    ImGui::Combo("faces", &faceChoice, "4 (tetra)\0" "6 (cube)\0" "8 (octa)\0" "12 (dodeca)\0" "20 (icosa)\0");
    const RegularSolidNumbers n = regularSolidNumbers(kFaceCounts[static_cast<std::size_t>(faceChoice)]);
    ImGui::Text("4 pi / %d = %.4f sr", n.faces, n.perFace.value());
    ImGui::Text("from one face's corners: %.4f sr", n.polygonRoute.value());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ui::wrappedText("whole sphere 4 pi = %.3f sr; a dodecahedron face is the lecture's \"1 sr\"",
                       kSphereSolidAngle.value());
    ImGui::PopStyleColor();
}

} // namespace radiant::app
