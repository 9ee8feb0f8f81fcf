#include "app/panels/DisplayPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/ui/HorizontalColourBar.h"
#include "app/ui/LegendUnit.h"

namespace radiant::app {
namespace {

void help(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

} // namespace

void DisplayPanel::draw() {
    render::DisplaySettings& s = settings_;
    const float labelRoom = ImGui::GetFontSize() * 7.0f;

    ImGui::SetNextItemWidth(-labelRoom);
    ImGui::SliderFloat("Exposure", &s.exposureStops, -8.0f, 8.0f, "%+.1f stops");
    help("Relative to the key below. Each stop doubles the light.\n"
         "Double-click to type; right-click resets.");
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) s.exposureStops = 0.0f;

    int key = static_cast<int>(s.exposureKey);
    ImGui::TextUnformatted("Key");
    ImGui::SameLine(labelRoom * 0.7f);
    ImGui::RadioButton("emitters", &key, static_cast<int>(render::ExposureKey::EnergyBalance));
    help("Fixed by the emitters: the mean radiosity the walls reach once all emitted power\n"
         "is absorbed. The view starts dark and brightens as the solve spreads the light.");
    ImGui::SameLine();
    ImGui::RadioButton("held", &key, static_cast<int>(render::ExposureKey::Held));
    help("Fixed at the solution shown when re-keyed (button or key K).");
    ImGui::SameLine();
    ImGui::RadioButton("auto", &key, static_cast<int>(render::ExposureKey::Automatic));
    help("The mean radiosity of the lit walls, every frame: always well exposed, but the\n"
         "solve hardly seems to brighten.");
    s.exposureKey = static_cast<render::ExposureKey>(key);
    ImGui::SetCursorPosX(labelRoom * 0.7f);  // under the radio buttons
    if (ImGui::SmallButton("Re-key on this solution (K)")) rekey(s);
    help("Hold the exposure that shows the solution on screen now at a middle tone.");

    int shading = s.shading == render::Shading::Smooth ? 0 : 1;
    ImGui::TextUnformatted("Shading");
    ImGui::SameLine(labelRoom * 0.7f);
    ImGui::RadioButton("smooth", &shading, 0);
    help("Gouraud: each vertex shows the area-weighted mean of its patches on the surface.");
    ImGui::SameLine();
    ImGui::RadioButton("flat", &shading, 1);
    help("Each patch shows its own radiosity: the solver's unknowns as they are.");
    s.shading = shading == 0 ? render::Shading::Smooth : render::Shading::Flat;

    int colour = static_cast<int>(s.colourMode);
    ImGui::RadioButton("light", &colour, static_cast<int>(render::ColourMode::ToneMapped));
    help("Radiosity through the exposure and tone curve: what an eye would see.");
    ImGui::SameLine();
    ImGui::RadioButton("false colour", &colour, static_cast<int>(render::ColourMode::FalseColour));
    help("Total radiosity B_r + B_g + B_b in W/m\xC2\xB2 through the viridis colour map;\n"
         "with photometric units on, the illuminance each patch receives, in lx.");
    ImGui::SameLine();
    ImGui::RadioButton("reflectance", &colour, static_cast<int>(render::ColourMode::Reflectance));
    help("Each surface in its material's reflectance: the scene as built, before light.");
    s.colourMode = static_cast<render::ColourMode>(colour);
    const bool falseColour = s.colourMode == render::ColourMode::FalseColour;
    if (falseColour) {
        ImGui::Indent();
        ImGui::Checkbox("Log scale", &s.logScale);
        ImGui::SameLine();
        ImGui::Checkbox("Isolines", &s.isolines);
        help("A contour at every tick of the legend.");
        if (ImGui::Checkbox("Manual range", &manualRange_) && manualRange_ && s.falseColourMaxW_m2 <= 0)
            s.falseColourMaxW_m2 = static_cast<float>(legend_ ? legend_().maxW_m2 : 1.0);
        if (manualRange_) {
            ImGui::SetNextItemWidth(-labelRoom);
            ImGui::DragFloat("Max", &s.falseColourMaxW_m2, std::max(s.falseColourMaxW_m2 * 0.01f, 1e-4f), 1e-4f, 1e7f,
                             s.photometric ? "%.4g lx" : "%.4g W/m\xC2\xB2", ImGuiSliderFlags_Logarithmic);
            s.falseColourMaxW_m2 = std::max(s.falseColourMaxW_m2, 1e-4f);
        } else {
            s.falseColourMaxW_m2 = 0.0f;
        }
        ImGui::Unindent();
        if (legend_) drawLegend(legend_());
    }

    ImGui::Spacing();
    ImGui::TextDisabled("Overlays");
    const float secondColumn = ImGui::GetFontSize() * 9.0f;
    ImGui::Checkbox("Wireframe", &s.wireframe);
    ImGui::SameLine(secondColumn);
    ImGui::Checkbox("Shooter", &s.highlightShooter);
    help("Outline the patch shot in the last step and tint the patches it changed.");
    ImGui::Checkbox("Links", &s.showLinks);
    help("Hierarchical radiosity's links between elements.");
    ImGui::SameLine(secondColumn);
    ImGui::Checkbox("Importance", &s.showImportance);
    help("Importance-driven radiosity's per-patch importance, relative to its maximum (magenta).");

    ImGui::Spacing();
    if (ImGui::Checkbox("Photometric units (lx, cd/m\xC2\xB2)", &s.photometric)) {
        // A manual maximum was in the other unit: the range goes back to automatic.
        manualRange_ = false;
        s.falseColourMaxW_m2 = 0.0f;
    }
    help("The Probe panel also reads illuminance in lux and luminance in cd/m\xC2\xB2, and false colour\n"
         "maps illuminance in lux (E = (B - M) / rho per band, the radiosity equation read backwards;\n"
         "a surface black in a band shows grey: B says nothing of the light it gets there). Converted from\n"
         "the three bands by Radiance's convention: luminous efficacy 179 lm/W and\n"
         "Y = 0.265 R + 0.670 G + 0.065 B, so E_v = 179 Y(E) and L_v = 179 Y(L).\n"
         "glTF lights given in candela and lux are read with the same 179 lm/W.");

    ImGui::Spacing();
    if (!editingScale_) scaleSlider_ = s.uiScale;
    ImGui::SetNextItemWidth(-labelRoom);
    // Applied when the slider is let go: rebuilding the font atlas under the cursor makes it jump.
    ImGui::SliderFloat("UI scale", &scaleSlider_, 0.75f, 2.5f, "%.2fx");
    help("Larger text and spacing for a projector.");
    editingScale_ = ImGui::IsItemActive();
    if (ImGui::IsItemDeactivatedAfterEdit()) s.uiScale = scaleSlider_;
}

void DisplayPanel::rekey(render::DisplaySettings& settings) {
    settings.exposureKey = render::ExposureKey::Held;
    ++settings.rekeyCount;
}

void DisplayPanel::drawLegend(const render::ColourLegend& legend) const {
    const float font = ImGui::GetFontSize();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float margin = font * 0.9f;  // half a label either side, so end labels stay in the panel
    const float width = std::max(ImGui::GetContentRegionAvail().x - 2.0f * margin, font * 4.0f);
    const float barHeight = font * 0.9f;
    const ImVec2 barLo(origin.x + margin, origin.y + font * 0.2f);
    const ImVec2 barHi(barLo.x + width, barLo.y + barHeight);

    // Viridis is smooth enough that 32 linear pieces are exact to the eye.
    drawHorizontalColourBar({barLo, barHi, 32, 0.3f, true},
                            [](double t) { return colourU32(render::viridis(t)); }, legend);
    ImGui::Dummy(ImVec2(width + 2 * margin, barHeight + font * 1.6f));
    ImGui::TextDisabled("%s, %s, %s, %s", legend.quantity, legendUnitForScreen(legend),
                        legend.logScale ? "log scale" : "linear",
                        settings_.falseColourMaxW_m2 > 0 ? "manual max" : "automatic max");
}

} // namespace radiant::app
