// The lecture's "one steradian": a dodecahedron's 12 faces share the sphere's 4 pi sr, 1.047 sr each.
// Shown two ways: 4 pi / n, and one face's solid angle from its vertices (Van Oosterom & Strackee),
// with the face of a regular solid built from its known vertex coordinates.
#include <imgui.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "app/panels/demos/LectureDemos.h"
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

} // namespace

RegularSolidNumbers regularSolidNumbers(int faces) {
    RegularSolidNumbers n;
    n.faces = faces;
    n.perFace = regularSolidFaceSolidAngle(faces);
    const std::vector<glm::dvec3> face = oneFace(faces);
    n.polygonRoute = polygonSolidAngle({0, 0, 0}, face);
    return n;
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
    ImGui::TextWrapped("whole sphere 4 pi = %.3f sr; a dodecahedron face is the lecture's \"1 sr\"",
                       kSphereSolidAngle.value());
    ImGui::PopStyleColor();
}

} // namespace radiant::app
