// The lecture's irradiance example: an isotropic point source P at height h over a plane.
// E(x) = I cos(theta) / r^2 with I = P / (4 pi sr), r^2 = h^2 + x^2, cos(theta) = h / r.
#include <imgui.h>

#include <cmath>
#include <vector>

#include "app/panels/demos/AxesPlot.h"
#include "app/panels/demos/DemoText.h"
#include "app/panels/demos/LectureDemos.h"
#include "radiometry/sources/PointSource.h"
#include "render/ColourScale.h"

namespace radiant::app {

PointSourceNumbers pointSourceNumbers(const PointSourceSettings& s) {
    PointSourceNumbers n;
    n.intensity = isotropicIntensity(Power(s.powerW));
    n.distance = Length(std::hypot(s.heightM, s.offsetM));
    n.cosIncidence = s.heightM / n.distance.value();
    n.irradiance = pointSourceIrradiance(n.intensity, n.distance, Radians(std::acos(n.cosIncidence)));
    n.directlyBelow = pointSourceIrradiance(n.intensity, Length(s.heightM), Radians(0.0));
    return n;
}

namespace {

// The plane shown: x across the view, z into it, y up; the measured point at the origin.
constexpr double kHalfWidth = 5.0, kHalfDepth = 3.5;
constexpr int kCellsX = 100, kCellsZ = 70;

/// E at a plane point (x, z) from the source at (offset, h, 0): the panel's function, by its
/// horizontal distance from the source.
double irradianceAt(const PointSourceSettings& s, double x, double z) {
    PointSourceSettings at = s;
    at.offsetM = std::hypot(x - s.offsetM, z);
    return pointSourceNumbers(at).irradiance.value();
}

} // namespace

DemoFraming PointSourceDemo::framing() const { return framingFrom({-0.4, 9.0, 11.6}, {-0.4, 0.3, 0.3}, 52); }

// The plane in false colour of E with isolines at the legend's round values, a colour bar with its
// ticks, the source over it with its numbers, the measured point at the origin, and the reading where
// the pointer rests on the plane.
render::DemoDrawing PointSourceDemo::picture(const std::optional<PickRay>& cursor) const {
    using namespace render::demo_colour;
    const PointSourceSettings& s = settings;
    const PointSourceNumbers n = pointSourceNumbers(s);
    const render::ColourLegend legend = render::makeLegend(n.directlyBelow.value(), false, 3);
    const double step = legend.linearStepW_m2();
    const auto colourOf = [&](double e) {
        const glm::dvec3 c = render::viridis(legend.position(e));
        return glm::vec4(point3(c.x, c.y, c.z), 1.0f);
    };
    render::DemoDrawing d;
    const auto corner = [&](int i, int k) {
        const double x = -kHalfWidth + 2 * kHalfWidth * i / kCellsX, z = -kHalfDepth + 2 * kHalfDepth * k / kCellsZ;
        const double e = irradianceAt(s, x, z);
        return render::DemoVertex{point3(x, 0, z), colourOf(e), static_cast<float>(e / step)};
    };
    for (int i = 0; i < kCellsX; ++i)
        for (int k = 0; k < kCellsZ; ++k) {
            const render::DemoVertex a = corner(i, k), b = corner(i + 1, k), c = corner(i + 1, k + 1), e = corner(i, k + 1);
            d.triangle(a, b, c);
            d.triangle(a, c, e);
        }
    d.loop({point3(-kHalfWidth, 0, -kHalfDepth), point3(kHalfWidth, 0, -kHalfDepth), point3(kHalfWidth, 0, kHalfDepth),
            point3(-kHalfWidth, 0, kHalfDepth)}, kAxis);

    // The colour bar standing at the plane's left edge (the source's label runs to the right), its
    // ticks the isolines' values.
    const double barX = -kHalfWidth - 0.9, barHeight = 3.0;
    for (int i = 0; i < 40; ++i) {
        const double y0 = barHeight * i / 40, y1 = barHeight * (i + 1) / 40;
        const double e0 = legend.maxW_m2 * i / 40, e1 = legend.maxW_m2 * (i + 1) / 40;
        const render::DemoVertex a{point3(barX, y0, 0), colourOf(e0), static_cast<float>(e0 / step)},
            b{point3(barX + 0.35, y0, 0), colourOf(e0), static_cast<float>(e0 / step)},
            c{point3(barX + 0.35, y1, 0), colourOf(e1), static_cast<float>(e1 / step)},
            e{point3(barX, y1, 0), colourOf(e1), static_cast<float>(e1 / step)};
        d.triangle(a, b, c);
        d.triangle(a, c, e);
    }
    for (const double tick : legend.ticksW_m2) {
        const double y = barHeight * legend.position(tick);
        d.line(point3(barX + 0.35, y, 0), point3(barX + 0.5, y, 0), kText);
        d.pinnedLabel(point3(barX + 0.55, y, 0), printed("%s", render::formatLegendTick(tick).c_str()));
    }
    d.label(point3(barX - 0.2, barHeight + 0.35, 0), "E (W/m^2)");

    // The source, its drop line, and the measured point at the origin.
    const glm::vec3 source = point3(s.offsetM, s.heightM, 0);
    d.sphere(source, 0.14f, kLight);
    d.dashedLine(source, point3(s.offsetM, 0, 0), 0.1f, kLight);
    d.label(source + glm::vec3(0.2f, 1.2f, 0),
            printed("source: P = %.0f W, I = P / 4 pi = %.3g W/sr\nh = %.2f m, below it E = I / h^2 = %.3g W/m^2",
                    s.powerW, n.intensity.value(), s.heightM, n.directlyBelow.value()), kLight);
    d.line(source, point3(0, 0, 0), kHighlight);
    d.circle(point3(0, 0.01, 0), {1, 0, 0}, {0, 0, 1}, 0.12f, kHighlight, 3.0f, 24);
    // Its numbers at the plane's front-left corner, clear of the source's and the cursor's.
    d.label(point3(-kHalfWidth + 0.2, 0, kHalfDepth - 0.4),
            printed("measured point (ring), %.2f m from the foot: r = %.2f m, cos theta = %.3f\nE = I cos theta / r^2 = %.4g W/m^2",
                    s.offsetM, n.distance.value(), n.cosIncidence, n.irradiance.value()), kHighlight);

    // The reading under the pointer.
    if (cursor && cursor->direction.y < -1e-6) {
        const double t = -cursor->origin.y / cursor->direction.y;
        const glm::dvec3 hit = cursor->origin + t * cursor->direction;
        if (t > 0 && std::abs(hit.x) <= kHalfWidth && std::abs(hit.z) <= kHalfDepth) {
            PointSourceSettings at = s;
            at.offsetM = std::hypot(hit.x - s.offsetM, hit.z);
            const PointSourceNumbers h = pointSourceNumbers(at);
            const glm::vec3 p = point3(hit.x, 0.01, hit.z);
            d.line(source, p, kProbe);
            d.circle(p, {1, 0, 0}, {0, 0, 1}, 0.1f, kProbe, 3.0f, 24);
            d.label(p + glm::vec3(0.2f, 0.25f, 0),
                    printed("cursor: E = %.4g W/m^2\nr = %.2f m, cos theta = %.3f", h.irradiance.value(),
                            h.distance.value(), h.cosIncidence), kProbe);
        }
    }
    return d;
}

void PointSourceDemo::draw() {
    auto& s = settings;
    float power = static_cast<float>(s.powerW), height = static_cast<float>(s.heightM), offset = static_cast<float>(s.offsetM);
    if (ImGui::SliderFloat("power P (W)", &power, 1, 1000, "%.0f W", ImGuiSliderFlags_Logarithmic)) s.powerW = power;
    if (ImGui::SliderFloat("height h (m)", &height, 0.1f, 5, "%.2f m")) s.heightM = height;
    if (ImGui::SliderFloat("source offset x (m)", &offset, -5, 5, "%.2f m")) s.offsetM = offset;
    const PointSourceNumbers n = pointSourceNumbers(s);
    ImGui::Text("I = P / 4 pi = %.4g W/sr", n.intensity.value());
    ImGui::Text("r = %.3f m, cos theta = %.3f", n.distance.value(), n.cosIncidence);
    ImGui::Text("E = I cos theta / r^2 = %.4g W/m^2", n.irradiance.value());
    ImGui::TextDisabled("below the source: %.4g W/m^2; double h -> 1/4", n.directlyBelow.value());
    // E along the plane through the measured point and the source's foot: the cos^3 falloff of a
    // lamp over a table.
    std::vector<double> xs(121), profile(121);
    for (std::size_t i = 0; i < profile.size(); ++i) {
        xs[i] = -5.0 + 10.0 * static_cast<double>(i) / static_cast<double>(profile.size() - 1);
        PointSourceSettings at = s;
        at.offsetM = xs[i] - s.offsetM;
        profile[i] = pointSourceNumbers(at).irradiance.value();
    }
    const double top = n.directlyBelow.value();
    drawAxesPlot(xs, profile, {-5, 5, false, "x (m)", {-5, -2.5, 0, 2.5, 5}},
                 {0, top * 1.05, false, "E (W/m^2)", {0, top / 2, top}}, 0.0);  // the measured point
}

} // namespace radiant::app
