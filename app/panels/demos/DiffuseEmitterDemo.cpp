// The lecture's diffuse emitter: the same radiance L in every direction from every point, so
// P = L A integral of cos(theta) d omega = L A pi, and the exitance B = P / A = pi L.
#include <imgui.h>

#include "app/panels/demos/LectureDemos.h"
#include "radiometry/sources/DiffuseEmitter.h"

namespace radiant::app {

DiffuseEmitterNumbers diffuseEmitterNumbers(const DiffuseEmitterSettings& s) {
    const Radiance radiance(s.radianceW_m2sr);
    return {diffuseEmitterPower(radiance, Area(s.areaM2)), radiosityFromRadiance(radiance),
            kHemisphereProjectedSolidAngle};
}

void DiffuseEmitterDemo::draw() {
    float radiance = static_cast<float>(settings.radianceW_m2sr), area = static_cast<float>(settings.areaM2);
    if (ImGui::SliderFloat("radiance L", &radiance, 1, 1e4f, "%.0f W/(m^2 sr)", ImGuiSliderFlags_Logarithmic))
        settings.radianceW_m2sr = radiance;
    if (ImGui::SliderFloat("area A", &area, 0.01f, 10, "%.2f m^2", ImGuiSliderFlags_Logarithmic)) settings.areaM2 = area;
    const DiffuseEmitterNumbers n = diffuseEmitterNumbers(settings);
    ImGui::Text("integral of cos theta d omega = %.5f sr (= pi)", n.projectedSolidAngle.value());
    ImGui::Text("P = L A pi = %.5g W", n.power.value());
    ImGui::Text("B = P / A = pi L = %.5g W/m^2", n.exitance.value());
    ImGui::TextDisabled("not 2 pi: grazing directions carry little (cos theta)");
}

} // namespace radiant::app
