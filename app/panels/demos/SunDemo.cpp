// The lecture's Sun example: L = P / (pi A) leaves the Sun and arrives unchanged (radiance is
// invariant along rays); only the solid angle the Sun subtends shrinks with distance, so E = L omega.
// The lecture's 6.7e-5 sr for Earth is rounded from pi R^2 / d^2 = 6.78e-5 sr.
#include <imgui.h>

#include <cmath>
#include <numbers>

#include "app/panels/demos/DemoText.h"
#include "app/panels/demos/LectureDemos.h"
#include "app/ui/WrappedText.h"
#include "radiometry/sources/SunExample.h"

namespace radiant::app {
namespace {

SunPlanetNumbers planet(const SunExample& sun, Length distance, SolidAngle lecture) {
    SunPlanetNumbers p;
    p.distance = distance;
    p.lectureSolidAngle = lecture;
    p.projectedAreaSolidAngle = sun.projectedAreaSolidAngle(distance);
    p.exactSolidAngle = sun.exactSolidAngle(distance);
    p.lectureIrradiance = sun.irradiance(lecture);
    p.irradiance = sun.irradiance(p.exactSolidAngle);
    return p;
}

/// A table cell of a few digits; the full value, and what it is, in its tooltip.
void cell(const char* shortFormat, const char* fullFormat, double value) {
    ImGui::TableNextColumn();
    ImGui::Text(shortFormat, value);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(fullFormat, value);
}

void planetRow(const char* name, const SunPlanetNumbers& p) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    cell("%.3g", "distance %.6g au", p.distance.value() / SunExample().astronomicalUnit.value());
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", p.exactSolidAngle.value());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("omega = %.6g sr (the Sun's spherical cap); pi R^2 / d^2 = %.6g sr; the lecture's: %.3g sr",
                          p.exactSolidAngle.value(), p.projectedAreaSolidAngle.value(), p.lectureSolidAngle.value());
    cell("%.5g", "E = L omega = %.8g W/m^2", p.irradiance.value());
}

} // namespace

SunNumbers sunNumbers() {
    const SunExample sun;
    return {sun.radiance(), sun.sunRadius(), planet(sun, sun.earthDistance(), sun.lectureEarthSolidAngle),
            planet(sun, sun.marsDistance(), sun.lectureMarsSolidAngle)};
}

namespace {

// The schematic's distance axis: x = kMetresPerDecade log10(d / 0.1 au), so 0.1 au .. 40 au fits.
constexpr double kMetresPerDecade = 2.2, kAxisFromAu = 0.1, kAxisToAu = 40;
constexpr float kSunRadius = 0.45f;  ///< the schematic Sun (not to scale)
double axisX(double au) { return kMetresPerDecade * std::log10(au / kAxisFromAu); }
// The E(d) plot above the planets: log10 E on y, kMetresPerDecadeOfE per decade, from E at 40 au.
constexpr double kPlotBase = 1.2, kMetresPerDecadeOfE = 0.42;

/// The cone a planet sees the schematic Sun in: apex at the planet, base the Sun's disc.
void cone(render::DemoDrawing& d, double au, const glm::vec4& colour) {
    const glm::vec3 apex = point3(axisX(au), 0, 0);
    constexpr int kSides = 40;
    glm::vec4 fill = colour;
    fill.w = 0.22f;
    for (int i = 0; i < kSides; ++i) {
        const auto rim = [&](int k) {
            const double phi = 2 * std::numbers::pi * k / kSides;
            return point3(0, kSunRadius * std::cos(phi), kSunRadius * std::sin(phi));
        };
        d.triangle({apex, fill}, {rim(i), fill}, {rim(i + 1), fill});
    }
    d.line(apex, {0, kSunRadius, 0}, colour, 1.5f);
    d.line(apex, {0, -kSunRadius, 0}, colour, 1.5f);
}

} // namespace

DemoFraming SunDemo::framing() const { return framingFrom({3.1, 1.4, 11.5}, {3.1, 0.7, 0.0}, 45); }

// The Sun, Earth, Mars and the slider's planet on a log-distance axis, each planet with the cone of
// the solid angle it sees the Sun in and its numbers (L the same everywhere, omega and E = L omega
// falling as 1 / d^2); above them E(d) on log-log axes, a line of slope -2.
render::DemoDrawing SunDemo::picture(const std::optional<PickRay>&) const {
    using namespace render::demo_colour;
    const SunExample sun;
    const SunNumbers n = sunNumbers();
    const SunPlanetNumbers yours = planet(sun, sun.astronomicalUnit * distanceAu,
                                          sun.projectedAreaSolidAngle(sun.astronomicalUnit * distanceAu));
    render::DemoDrawing d;
    d.sphere({0, 0, 0}, kSunRadius, kLight, 16);
    d.label(point3(-0.9, kSunRadius + 0.55, 0),
            printed("Sun: L = P / (pi A)\n= %.3g W/(m^2 sr)", n.radiance.value()), kLight);

    // The distance axis with its ticks.
    const float axisY = -1.9f;
    d.line(point3(axisX(0.2), axisY, 0), point3(axisX(kAxisToAu), axisY, 0), kAxis);
    for (const double au : {0.3, 1.0, 3.0, 10.0, 30.0}) {
        d.line(point3(axisX(au), axisY, 0), point3(axisX(au), axisY - 0.12, 0), kAxis);
        d.label(point3(axisX(au) - 0.15, axisY - 0.35, 0), printed("%g au", au), kAxis);
    }
    d.label(point3(axisX(kAxisToAu) - 2.6, axisY - 0.85, 0), "distance d, log scale (not to scale)", kAxis);

    // E(d) on log-log axes: log10 E(d) / E(40 au) = 2 log10(40 au / d).
    const auto plotY = [&](double au) { return kPlotBase + kMetresPerDecadeOfE * 2 * std::log10(kAxisToAu / au); };
    d.line(point3(axisX(0.3), plotY(0.3), 0), point3(axisX(kAxisToAu), plotY(kAxisToAu), 0), kHighlight, 3.0f);
    d.label(point3(axisX(0.25), plotY(0.3) + 0.45, 0), "E = L omega, falling as 1 / d^2 (log-log)", kHighlight);

    struct Shown { const char* name; const SunPlanetNumbers* numbers; double au; glm::vec4 colour; float labelY; };
    const Shown planets[] = {{"Earth", &n.earth, 1.0, kProbe, 0.55f},
                             {"Mars", &n.mars, sun.marsDistanceAu, glm::vec4(1.0f, 0.5f, 0.4f, 1.0f), -1.25f},
                             {"your planet", &yours, distanceAu, kText, 0.0f}};
    for (const Shown& p : planets) {
        const double x = axisX(p.au);
        cone(d, p.au, p.colour);
        d.sphere(point3(x, 0, 0), 0.12f, p.colour, 10);
        d.dashedLine(point3(x, 0.15, 0), point3(x, plotY(p.au), 0), 0.08f, p.colour, 1.5f);
        d.sphere(point3(x, plotY(p.au), 0), 0.06f, p.colour, 8);
        // The movable planet's numbers beside its point on the plot, clear of Earth's and Mars'.
        const bool movable = p.numbers == &yours;
        d.label(movable ? point3(x + 0.15, plotY(p.au) + 0.2, 0) : point3(x - 0.1, p.labelY, 0),
                printed("%s, %.4g au\nomega = %.4g sr\nE = L omega = %.4g W/m^2\nL = %.3g W/(m^2 sr) (the same)", p.name, p.au,
                        p.numbers->exactSolidAngle.value(), p.numbers->irradiance.value(), n.radiance.value()),
                p.colour);
    }
    return d;
}

void SunDemo::draw() {
    const SunExample sun;
    const SunNumbers n = sunNumbers();
    ImGui::Text("P = %.3g W, A = %.3g m^2", sun.power.value(), sun.surfaceArea.value());
    ImGui::Text("L = P / (pi A) = %.4g W/(m^2 sr)", n.radiance.value());
    ImGui::TextDisabled("the same L reaches Earth and Mars: radiance is invariant along a ray");
    float au = static_cast<float>(distanceAu);
    if (ImGui::SliderFloat("your planet", &au, 0.3f, 40.0f, "%.2f au", ImGuiSliderFlags_Logarithmic)) distanceAu = au;
    const SunPlanetNumbers yours = planet(sun, sun.astronomicalUnit * distanceAu, sun.projectedAreaSolidAngle(sun.astronomicalUnit * distanceAu));
    // Four narrow columns with the units in two-line headers fit a 14-em sidebar; the full values
    // are in each cell's tooltip.
    if (ImGui::BeginTable("##sun", 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerH)) {
        ImGui::PushTextWrapPos(-1.0f);  // cells stay whole: the sidebar wraps prose, and a column fitted to wrapped text shrinks to a letter
        for (const char* h : {"", "d\n(au)", "omega\n(sr)", "E\n(W/m^2)"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        planetRow("Earth", n.earth);
        planetRow("Mars", n.mars);
        planetRow("yours", yours);
        ImGui::PopTextWrapPos();
        ImGui::EndTable();
    }
    ui::wrappedText("Lecture: %.4g W on 1 m^2 at Earth (omega rounded to 6.7e-5 sr); from the geometry "
                       "(R = %.3g m, 1 au) omega = %.4g sr and E = %.1f W/m^2: %.1f %% more.",
                       n.earth.lectureIrradiance.value(), n.sunRadius.value(), n.earth.exactSolidAngle.value(),
                       n.earth.irradiance.value(), 100.0 * (n.earth.irradiance.value() / n.earth.lectureIrradiance.value() - 1));
}

} // namespace radiant::app
