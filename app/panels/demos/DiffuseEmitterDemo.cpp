// The lecture's diffuse emitter: the same radiance L in every direction from every point, so
// P = L A integral of cos(theta) d omega = L A pi, and the exitance B = P / A = pi L.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/panels/demos/DemoText.h"
#include "app/panels/demos/LectureDemos.h"
#include "radiometry/sources/DiffuseEmitter.h"

namespace radiant::app {

DiffuseEmitterNumbers diffuseEmitterNumbers(const DiffuseEmitterSettings& s) {
    const Radiance radiance(s.radianceW_m2sr);
    return {diffuseEmitterPower(radiance, Area(s.areaM2)), radiosityFromRadiance(radiance),
            kHemisphereProjectedSolidAngle};
}

// The emitter left of the view's centre, so that the probes' labels, which read to the right, fit
// beside their probes at a projector's UI scale of 1.5 (from farther away and centred on the emitter,
// the three were pushed down into each other and over the rays); framed for a lesson's wide view.
DemoFraming DiffuseEmitterDemo::framing() const {
    DemoFraming framing = framingFrom({2.2, 2.7, 7.2}, {2.2, 1.5, 0.0}, 50);
    framing.framedAspect = 1.6;
    return framing;
}

// The emitter as a square of area A on the floor, brighter as L grows; three probes at 0, 45 and 75
// degrees from its normal, each with its line of sight and its reading: the intensity I = L A cos
// theta falls with the projected area A cos theta, so L = I / (A cos theta) reads the same from each.
// The intensity lobe (a circle through the emitter's centre, diameter L A) shows I against theta.
render::DemoDrawing DiffuseEmitterDemo::picture(const std::optional<PickRay>&) const {
    using namespace render::demo_colour;
    const DiffuseEmitterNumbers n = diffuseEmitterNumbers(settings);
    const double side = std::sqrt(settings.areaM2), h = side / 2;
    render::DemoDrawing d;
    // Brightness on a log scale of L over the slider's 1 .. 1e4 W/(m^2 sr).
    const float glow = static_cast<float>(0.35 + 0.65 * std::clamp(std::log10(settings.radianceW_m2sr) / 4.0, 0.0, 1.0));
    d.quad(point3(-h, 0, -h), point3(h, 0, -h), point3(h, 0, h), point3(-h, 0, h), glm::vec4(glm::vec3(kLight) * glow, 1.0f));
    d.loop({point3(-h, 0, -h), point3(h, 0, -h), point3(h, 0, h), point3(-h, 0, h)}, kLight);
    d.label(point3(-h, 0, h + 0.9),
            printed("A = %.2f m^2, L = %.4g W/(m^2 sr)\nP = pi L A = %.5g W\nB = pi L = %.5g W/m^2", settings.areaM2,
                    settings.radianceW_m2sr, n.power.value(), n.exitance.value()), kLight);

    // Lambert's intensity lobe in the plane of the probes: I(theta) = I0 cos theta is a circle of
    // diameter I0 tangent to the emitter at its centre, drawn at a fixed size (its scale in the label).
    const float lobe = 1.1f;
    d.circle({0, lobe, 0}, {1, 0, 0}, {0, 1, 0}, lobe, kGrid, 2.0f, 72);
    const double peakIntensity = settings.radianceW_m2sr * settings.areaM2;
    d.labelLeftOf(point3(-1.15 * lobe, 1.8 * lobe, 0), printed("intensity lobe\nI = L A cos theta\n(top: %.4g W/sr)", peakIntensity), kAxis);

    constexpr double kProbeDistance = 3.0;
    for (const double degrees : {0.0, 45.0, 75.0}) {
        const double theta = degrees * std::numbers::pi / 180.0;
        const glm::vec3 probe = point3(kProbeDistance * std::sin(theta), kProbeDistance * std::cos(theta), 0);
        const double cosTheta = std::cos(theta);
        const double intensity = peakIntensity * cosTheta, projectedArea = settings.areaM2 * cosTheta;
        d.sphere(probe, 0.09f, kProbe);
        d.line(probe, {0, 0, 0}, kProbe, 2.5f);
        // The lobe's radius in this direction: I(theta) on the lobe's scale.
        d.line({0, 0, 0}, glm::normalize(probe) * (2 * lobe * static_cast<float>(cosTheta)), kHighlight, 4.0f);
        d.label(probe + glm::vec3(0.18f, 0.1f, 0),
                printed("theta = %.0f deg: I = %.4g W/sr\nA cos theta = %.3g m^2\nL = I / (A cos theta) = %.4g W/(m^2 sr)",
                        degrees, intensity, projectedArea, intensity / projectedArea), kProbe);
    }
    return d;
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
