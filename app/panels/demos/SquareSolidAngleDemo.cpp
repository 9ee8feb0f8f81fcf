// Omega = A / R^2 is the lecture's definition for a small, distant, facing area. For a square of side
// s centred on the axis at distance R the exact value is four corner rectangles,
// 4 atan((s/2)^2 / (R sqrt((s/2)^2 + (s/2)^2 + R^2))); A / R^2 overshoots as the square comes close.
#include <imgui.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "app/panels/demos/AxesPlot.h"
#include "app/panels/demos/DemoText.h"
#include "app/panels/demos/LectureDemos.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"

namespace radiant::app {

SquareSolidAngleNumbers squareSolidAngleNumbers(const SquareSolidAngleSettings& s) {
    const Length half(s.sideM / 2);
    SquareSolidAngleNumbers n;
    n.exact = cornerRectangleSolidAngle(half, half, Length(s.distanceM)) * 4.0;
    n.smallArea = smallAreaSolidAngle(Area(s.sideM * s.sideM), Length(s.distanceM));
    n.relativeError = n.smallArea.value() / n.exact.value() - 1.0;
    return n;
}

DemoFraming SquareSolidAngleDemo::framing() const { return framingFrom({2.4, 2.5, 4.0}, {0.2, 0.8, 0.0}, 50); }

// The point at the origin under its unit hemisphere (meridians, parallels and axes with ticks), the
// square facing it at height R, the pyramid of rays to its corners, and the square's projection onto
// the unit hemisphere: a spherical patch whose area is the solid angle.
render::DemoDrawing SquareSolidAngleDemo::picture(const std::optional<PickRay>&) const {
    using namespace render::demo_colour;
    const SquareSolidAngleNumbers n = squareSolidAngleNumbers(settings);
    const double h = settings.sideM / 2, r = settings.distanceM;
    render::DemoDrawing d;

    // The unit hemisphere: parallels every 15 degrees of theta, meridians every 30 degrees of phi.
    for (int ring = 1; ring <= 6; ++ring) {
        const double theta = ring * std::numbers::pi / 12;
        d.circle(point3(0, std::cos(theta), 0), {1, 0, 0}, {0, 0, 1}, static_cast<float>(std::sin(theta)),
                 ring == 6 ? kAxis : kGrid, ring == 6 ? 2.0f : 1.2f);
    }
    for (int meridian = 0; meridian < 6; ++meridian) {
        const double phi = meridian * std::numbers::pi / 6;
        std::vector<glm::vec3> arc;
        for (int k = 0; k <= 24; ++k) {
            const double theta = std::numbers::pi * (k / 24.0 - 0.5);
            arc.push_back(point3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
        for (std::size_t k = 0; k + 1 < arc.size(); ++k) d.line(arc[k], arc[k + 1], kGrid, 1.2f);
    }
    // Axes through the point, ticks every 0.25 m, labelled at 1 m.
    const glm::vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const char* names[] = {"x", "y (normal)", "z"};
    for (int a = 0; a < 3; ++a) {
        const glm::vec3 along = axes[a], tickSide = a == 1 ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        d.arrow({0, 0, 0}, 1.35f * along, 0.08f, kAxis, 2.0f);
        for (int t = 1; t <= 5; ++t) {
            const glm::vec3 at = 0.25f * static_cast<float>(t) * along;
            d.line(at, at + 0.05f * tickSide, kAxis, 2.0f);
        }
        d.label(1.4f * along, printed("%s", names[a]), kAxis);
        d.pinnedLabel(along + 0.08f * tickSide + glm::vec3(0.03f, 0.05f, 0), "1 m", kAxis);
    }
    d.sphere({0, 0, 0}, 0.035f, kText, 8);

    // The square at height R, facing down at the point, and the rays to its corners.
    const glm::vec3 corners[] = {point3(-h, r, -h), point3(h, r, -h), point3(h, r, h), point3(-h, r, h)};
    glm::vec4 veil = kSurface;
    veil.w = 0.45f;
    d.quad(corners[0], corners[1], corners[2], corners[3], veil);
    d.loop({corners[0], corners[1], corners[2], corners[3]}, kText, 2.5f);
    for (const glm::vec3& c : corners) d.line({0, 0, 0}, c, kProbe, 1.5f);
    d.label(corners[2] + glm::vec3(0.1f, 0.1f, 0),
            printed("square: s = %.2f m at R = %.2f m\nA / R^2 = %.4f sr (%+.1f %%)", settings.sideM, r,
                    n.smallArea.value(), 100.0 * n.relativeError), kText);

    // Its projection: each point of the square pushed along its ray onto the unit sphere.
    constexpr int kCells = 24;
    const auto onSphere = [&](int i, int k) {
        const glm::dvec3 p{-h + 2 * h * i / kCells, r, -h + 2 * h * k / kCells};
        const glm::dvec3 u = glm::normalize(p);
        return render::DemoVertex{point3(u.x, u.y, u.z), kHighlight};
    };
    for (int i = 0; i < kCells; ++i)
        for (int k = 0; k < kCells; ++k) {
            const render::DemoVertex a = onSphere(i, k), b = onSphere(i + 1, k), c = onSphere(i + 1, k + 1), e = onSphere(i, k + 1);
            d.triangle(a, b, c);
            d.triangle(a, c, e);
        }
    // Its area beside the hemisphere, a leader line from the patch's corner.
    const glm::vec3 patchCorner = onSphere(kCells, kCells).position, labelAt{1.15f, 0.9f, 0.0f};
    d.line(patchCorner, labelAt, kHighlight, 1.5f);
    d.label(labelAt,
            printed("its projection on the unit sphere:\narea = Omega = %.4f sr", n.exact.value()), kHighlight);
    return d;
}

void SquareSolidAngleDemo::draw() {
    float side = static_cast<float>(settings.sideM), distance = static_cast<float>(settings.distanceM);
    if (ImGui::SliderFloat("side s", &side, 0.01f, 5, "%.2f m", ImGuiSliderFlags_Logarithmic)) settings.sideM = side;
    if (ImGui::SliderFloat("distance R", &distance, 0.05f, 20, "%.2f m", ImGuiSliderFlags_Logarithmic))
        settings.distanceM = distance;
    const SquareSolidAngleNumbers n = squareSolidAngleNumbers(settings);
    ImGui::Text("exact   Omega = %.5f sr", n.exact.value());
    ImGui::Text("A / R^2       = %.5f sr  (%+.2f %%)", n.smallArea.value(), 100.0 * n.relativeError);
    ImGui::TextDisabled("the exact value never reaches 2 pi sr; A / R^2 grows without bound");
    // The overshoot of A / R^2 against R / s on log-log axes: it spans five decades.
    std::vector<double> ratio(100), error(100);
    for (std::size_t i = 0; i < error.size(); ++i) {
        SquareSolidAngleSettings at = settings;
        ratio[i] = std::pow(10.0, -1.0 + 2.5 * static_cast<double>(i) / 99.0);
        at.distanceM = settings.sideM * ratio[i];
        error[i] = 100.0 * squareSolidAngleNumbers(at).relativeError;
    }
    drawAxesPlot(ratio, error, {0.1, 31.6, true, "R / s (log)", {0.1, 1, 10}},
                 {0.01, 3000, true, "A / R^2 overshoot (%, log)", {0.01, 1, 100}}, settings.distanceM / settings.sideM);
}

} // namespace radiant::app
