// The lecture's Sun example: L = P / (pi A) leaves the Sun and arrives unchanged (radiance is
// invariant along rays); only the solid angle the Sun subtends shrinks with distance, so E = L omega.
// The lecture's 6.7e-5 sr for Earth is rounded from pi R^2 / d^2 = 6.78e-5 sr.
#include <imgui.h>

#include "app/panels/demos/LectureDemos.h"
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

void row(const char* name, const SunPlanetNumbers& p) {
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
        row("Earth", n.earth);
        row("Mars", n.mars);
        row("yours", yours);
        ImGui::PopTextWrapPos();
        ImGui::EndTable();
    }
    ImGui::TextWrapped("Lecture: %.4g W on 1 m^2 at Earth (omega rounded to 6.7e-5 sr); from the geometry "
                       "(R = %.3g m, 1 au) omega = %.4g sr and E = %.1f W/m^2: %.1f %% more.",
                       n.earth.lectureIrradiance.value(), n.sunRadius.value(), n.earth.exactSolidAngle.value(),
                       n.earth.irradiance.value(), 100.0 * (n.earth.irradiance.value() / n.earth.lectureIrradiance.value() - 1));
}

} // namespace radiant::app
