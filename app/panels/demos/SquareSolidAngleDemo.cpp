// Omega = A / R^2 is the lecture's definition for a small, distant, facing area. For a square of side
// s centred on the axis at distance R the exact value is four corner rectangles,
// 4 atan((s/2)^2 / (R sqrt((s/2)^2 + (s/2)^2 + R^2))); A / R^2 overshoots as the square comes close.
#include <imgui.h>

#include <cmath>
#include <vector>

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

void SquareSolidAngleDemo::draw() {
    float side = static_cast<float>(settings.sideM), distance = static_cast<float>(settings.distanceM);
    if (ImGui::SliderFloat("side s", &side, 0.01f, 5, "%.2f m", ImGuiSliderFlags_Logarithmic)) settings.sideM = side;
    if (ImGui::SliderFloat("distance R", &distance, 0.05f, 20, "%.2f m", ImGuiSliderFlags_Logarithmic))
        settings.distanceM = distance;
    const SquareSolidAngleNumbers n = squareSolidAngleNumbers(settings);
    ImGui::Text("exact   Omega = %.5f sr", n.exact.value());
    ImGui::Text("A / R^2       = %.5f sr  (%+.2f %%)", n.smallArea.value(), 100.0 * n.relativeError);
    ImGui::TextDisabled("the exact value never reaches 2 pi sr; A / R^2 grows without bound");
    std::vector<float> error(100);
    for (std::size_t i = 0; i < error.size(); ++i) {
        SquareSolidAngleSettings at = settings;
        at.distanceM = settings.sideM * std::pow(10.0, -1.0 + 2.5 * static_cast<double>(i) / 99.0);
        error[i] = static_cast<float>(100.0 * squareSolidAngleNumbers(at).relativeError);
    }
    ImGui::PlotLines("##err", error.data(), static_cast<int>(error.size()), 0, "A/R^2 error (%) for R/s 0.1 .. 30", 0.0f,
                     100.0f, {ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 5});
}

} // namespace radiant::app
