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

void row(const char* name, const SunPlanetNumbers& p) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn(); ImGui::TextUnformatted(name);
    ImGui::TableNextColumn(); ImGui::Text("%.4g m", p.distance.value());
    ImGui::TableNextColumn(); ImGui::Text("%.3g sr", p.lectureSolidAngle.value());
    ImGui::TableNextColumn(); ImGui::Text("%.4g sr", p.exactSolidAngle.value());
    ImGui::TableNextColumn(); ImGui::Text("%.1f W/m^2", p.irradiance.value());
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
    if (ImGui::BeginTable("##sun", 5, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerH)) {
        for (const char* h : {"", "distance", "lecture omega", "omega", "E = L omega"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        row("Earth", n.earth);
        row("Mars", n.mars);
        row("yours", yours);
        ImGui::EndTable();
    }
    ImGui::TextWrapped("Lecture: %.4g W on 1 m^2 at Earth (omega rounded to 6.7e-5 sr); from the geometry "
                       "(R = %.3g m, 1 au) omega = %.4g sr and E = %.1f W/m^2: %.1f %% more.",
                       n.earth.lectureIrradiance.value(), n.sunRadius.value(), n.earth.exactSolidAngle.value(),
                       n.earth.irradiance.value(), 100.0 * (n.earth.irradiance.value() / n.earth.lectureIrradiance.value() - 1));
}

} // namespace radiant::app
