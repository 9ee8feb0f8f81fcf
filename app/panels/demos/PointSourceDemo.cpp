// The lecture's irradiance example: an isotropic point source P at height h over a plane.
// E(x) = I cos(theta) / r^2 with I = P / (4 pi sr), r^2 = h^2 + x^2, cos(theta) = h / r.
#include <imgui.h>

#include <cmath>
#include <vector>

#include "app/panels/demos/LectureDemos.h"
#include "radiometry/sources/PointSource.h"

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

void PointSourceDemo::draw() {
    auto& s = settings;
    float power = static_cast<float>(s.powerW), height = static_cast<float>(s.heightM), offset = static_cast<float>(s.offsetM);
    if (ImGui::SliderFloat("power P (W)", &power, 1, 1000, "%.0f W", ImGuiSliderFlags_Logarithmic)) s.powerW = power;
    if (ImGui::SliderFloat("height h (m)", &height, 0.1f, 5, "%.2f m")) s.heightM = height;
    if (ImGui::SliderFloat("offset x (m)", &offset, -5, 5, "%.2f m")) s.offsetM = offset;
    const PointSourceNumbers n = pointSourceNumbers(s);
    ImGui::Text("I = P / 4 pi = %.4g W/sr", n.intensity.value());
    ImGui::Text("r = %.3f m, cos theta = %.3f", n.distance.value(), n.cosIncidence);
    ImGui::Text("E = I cos theta / r^2 = %.4g W/m^2", n.irradiance.value());
    ImGui::TextDisabled("below the source: %.4g W/m^2; double h -> 1/4", n.directlyBelow.value());
    // E along the plane: the cos^3 falloff of a lamp over a table.
    std::vector<float> profile(121);
    for (std::size_t i = 0; i < profile.size(); ++i) {
        PointSourceSettings at = s;
        at.offsetM = -5.0 + 10.0 * static_cast<double>(i) / static_cast<double>(profile.size() - 1);
        profile[i] = static_cast<float>(pointSourceNumbers(at).irradiance.value());
    }
    ImGui::PlotLines("##E(x)", profile.data(), static_cast<int>(profile.size()), 0, "E(x), x from -5 to 5 m", 0.0f,
                     static_cast<float>(n.directlyBelow.value()) * 1.05f,
                     {ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 5});
}

} // namespace radiant::app
