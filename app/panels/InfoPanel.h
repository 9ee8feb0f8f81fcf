#pragma once
// Info: frame time and rate, the GL driver and context, the UI scale, and the controls.
#include <string>

#include "app/panels/Panel.h"
#include "render/GlContext.h"

namespace radiant::app {

class FrameStats;
class ImGuiLayer;

class InfoPanel final : public Panel {
public:
    InfoPanel(const FrameStats& frames, render::GlInfo gl, std::string fallbackNote, ImGuiLayer& ui)
        : frames_(frames), gl_(std::move(gl)), fallbackNote_(std::move(fallbackNote)), ui_(ui) {}

    [[nodiscard]] const char* title() const override { return "Info"; }
    void draw() override;

private:
    const FrameStats& frames_;
    render::GlInfo gl_;
    std::string fallbackNote_;
    ImGuiLayer& ui_;
    float scaleSlider_ = 1.0f;
    bool editingScale_ = false;
};

} // namespace radiant::app
