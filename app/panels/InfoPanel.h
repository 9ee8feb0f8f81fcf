#pragma once
// Info: frame time and rate, the GL driver and context, and the mouse and keyboard controls.
// (The UI scale lives in the Display panel.)
#include <string>

#include "app/panels/Panel.h"
#include "render/GlContext.h"

namespace radiant::app {

class FrameStats;

class InfoPanel final : public Panel {
public:
    InfoPanel(const FrameStats& frames, render::GlInfo gl, std::string fallbackNote)
        : frames_(frames), gl_(std::move(gl)), fallbackNote_(std::move(fallbackNote)) {}

    [[nodiscard]] const char* title() const override { return "Info"; }
    void draw() override;

private:
    const FrameStats& frames_;
    render::GlInfo gl_;
    std::string fallbackNote_;
};

} // namespace radiant::app
