// Radiance is per unit projected area: a receiver tilted by theta from a source of radiance L and
// small solid angle omega intercepts the beam over cos(theta) of its area, so its irradiance is
// E = L omega cos(theta) while the radiance it sees along the ray stays L.
#include <imgui.h>

#include <cmath>

#include "app/panels/demos/LectureDemos.h"
#include "radiometry/sources/DistantSource.h"
#include "radiometry/units/Angle.h"

namespace radiant::app {

RadianceIrradianceNumbers radianceIrradianceNumbers(const RadianceIrradianceSettings& s) {
    const Radians tilt = Degrees(s.tiltDeg);
    RadianceIrradianceNumbers n;
    n.radiance = Radiance(s.radianceW_m2sr);
    n.irradiance = distantSourceIrradiance(n.radiance, SolidAngle(s.sourceSolidAngleSr), tilt);
    n.projectedAreaPerM2 = std::max(0.0, std::cos(tilt.value()));
    return n;
}

void RadianceIrradianceDemo::draw() {
    auto& s = settings;
    float radiance = static_cast<float>(s.radianceW_m2sr), omega = static_cast<float>(s.sourceSolidAngleSr),
          tilt = static_cast<float>(s.tiltDeg);
    if (ImGui::SliderFloat("source L", &radiance, 1, 1e5f, "%.0f W/(m^2 sr)", ImGuiSliderFlags_Logarithmic))
        s.radianceW_m2sr = radiance;
    if (ImGui::SliderFloat("source omega", &omega, 1e-5f, 0.1f, "%.2e sr", ImGuiSliderFlags_Logarithmic))
        s.sourceSolidAngleSr = omega;
    if (ImGui::SliderFloat("receiver tilt theta", &tilt, 0, 90, "%.0f deg")) s.tiltDeg = tilt;
    const RadianceIrradianceNumbers n = radianceIrradianceNumbers(s);
    ImGui::Text("radiance along the ray: %.4g W/(m^2 sr) (any tilt)", n.radiance.value());
    ImGui::Text("projected area: %.3f m^2 per m^2 (cos theta)", n.projectedAreaPerM2);
    ImGui::Text("irradiance E = L omega cos theta = %.4g W/m^2", n.irradiance.value());
}

} // namespace radiant::app
