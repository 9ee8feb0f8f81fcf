// Radiance is per unit projected area: a receiver tilted by theta from a source of radiance L and
// small solid angle omega intercepts the beam over cos(theta) of its area, so its irradiance is
// E = L omega cos(theta) while the radiance it sees along the ray stays L.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "app/panels/demos/DemoText.h"
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

DemoFraming RadianceIrradianceDemo::framing() const { return framingFrom({5.4, 3.0, -2.2}, {0.0, 1.4, 0.2}, 50); }

// A receiver of 1 m^2 at the origin, turned by theta about x, under a beam from a distant source
// straight above: the parallel rays it intercepts fill a cross-section of cos theta m^2 (drawn
// dashed above it), so E = L omega cos theta; its brightness follows E, its normal and the angle
// theta are marked, and the radiance along each ray is L whatever the tilt.
render::DemoDrawing RadianceIrradianceDemo::picture(const std::optional<PickRay>&) const {
    using namespace render::demo_colour;
    const RadianceIrradianceNumbers n = radianceIrradianceNumbers(settings);
    const double theta = settings.tiltDeg * std::numbers::pi / 180.0, c = std::cos(theta), sn = std::sin(theta);
    // The receiver's corners: x along the tilt axis, the other side tilted down towards -z... +z.
    const auto onReceiver = [&](double x, double v) { return point3(x, v * sn, v * c); };
    render::DemoDrawing d;
    const float shade = static_cast<float>(0.18 + 0.75 * n.projectedAreaPerM2);
    d.quad(onReceiver(-0.5, -0.5), onReceiver(0.5, -0.5), onReceiver(0.5, 0.5), onReceiver(-0.5, 0.5),
           glm::vec4(glm::vec3(kSurface) * 0.3f + glm::vec3(kLight) * shade * 0.8f, 1.0f));
    d.loop({onReceiver(-0.5, -0.5), onReceiver(0.5, -0.5), onReceiver(0.5, 0.5), onReceiver(-0.5, 0.5)}, kText, 2.5f);
    d.label(onReceiver(0.55, -0.5) + glm::vec3(0.0f, -0.35f, 0.0f),
            printed("receiver, 1 m^2, tilted theta = %.0f deg\nE = L omega cos theta = %.4g W/m^2", settings.tiltDeg,
                    n.irradiance.value()), kHighlight);

    // The normal and the angle from the beam's direction (straight up) to it.
    const glm::vec3 normal = point3(0, c, -sn);
    d.arrow({0, 0, 0}, 1.1f * normal, 0.1f, kProbe, 3.0f);
    d.line({0, 0, 0}, {0, 1.3f, 0}, kAxis, 1.5f);
    std::vector<glm::vec3> arc;
    for (int k = 0; k <= 16; ++k) {
        const double a = theta * k / 16;
        arc.push_back(point3(0, 0.55 * std::cos(a), -0.55 * std::sin(a)));
    }
    for (std::size_t k = 0; k + 1 < arc.size(); ++k) d.line(arc[k], arc[k + 1], kProbe, 2.0f);
    d.label(point3(0, 0.75, -0.35), printed("theta = %.0f deg", settings.tiltDeg), kProbe);

    // The source far above, and its parallel rays down to the receiver.
    const float top = 3.2f;
    d.sphere({0, top, 0}, 0.16f, kLight, 12);
    d.label(glm::vec3(0.25f, top + 0.1f, 0.0f),
            printed("distant source: L = %.4g W/(m^2 sr), omega = %.2e sr", n.radiance.value(), settings.sourceSolidAngleSr),
            kLight);
    for (const double x : {-0.4, 0.0, 0.4})
        for (const double v : {-0.4, 0.0, 0.4}) {
            const glm::vec3 hit = onReceiver(x, v);
            d.line(glm::vec3(hit.x, top - 0.3f, hit.z), hit, kLight, 1.5f);
        }
    d.label(point3(-0.45, top - 0.85, 0.0), printed("radiance along each ray: L = %.4g W/(m^2 sr) (any tilt)", n.radiance.value()), kLight);

    // The beam's cross-section the receiver intercepts: 1 m by cos theta m.
    const float y = 1.9f;
    const float halfDepth = static_cast<float>(0.5 * c);
    d.loop({{-0.5f, y, -halfDepth}, {0.5f, y, -halfDepth}, {0.5f, y, halfDepth}, {-0.5f, y, halfDepth}}, kHighlight, 2.5f);
    glm::vec4 veil = kHighlight;
    veil.w = 0.25f;
    d.quad({-0.5f, y, -halfDepth}, {0.5f, y, -halfDepth}, {0.5f, y, halfDepth}, {-0.5f, y, halfDepth}, veil);
    d.label(glm::vec3(0.6f, y, 0.0f), printed("beam intercepted: cos theta = %.3f m^2 per m^2", n.projectedAreaPerM2),
            kHighlight);
    return d;
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
