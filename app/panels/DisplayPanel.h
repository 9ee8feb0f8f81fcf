#pragma once
// Display: how radiosity is shown - exposure and what it is keyed on, smooth/flat shading, false colour with its legend in
// W/m^2 (linear or log, automatic or manual range, isolines), overlays (wireframe, last shooter,
// hierarchical links, importance) and the UI scale for projectors. Edits a DisplaySettings the lab
// owns and hands to the PatchRenderer each frame.
#include <functional>

#include "app/panels/Panel.h"
#include "render/ColourScale.h"
#include "render/DisplaySettings.h"

namespace radiant::app {

class DisplayPanel final : public Panel {
public:
    /// `legend` returns the range false colour currently maps (PatchRenderer::legend()); it is called
    /// while drawing, so it may follow a renderer that the lab replaces.
    DisplayPanel(render::DisplaySettings& settings, std::function<render::ColourLegend()> legend)
        : settings_(settings), legend_(std::move(legend)) {}

    [[nodiscard]] const char* title() const override { return "Display"; }
    void draw() override;
    /// Holds the exposure key of the solution shown now (the Re-key button and key K).
    static void rekey(render::DisplaySettings& settings);

private:
    void drawLegend(const render::ColourLegend& legend) const;

    render::DisplaySettings& settings_;
    std::function<render::ColourLegend()> legend_;
    bool manualRange_ = false;
    float scaleSlider_ = 1.0f;
    bool editingScale_ = false;
};

} // namespace radiant::app
