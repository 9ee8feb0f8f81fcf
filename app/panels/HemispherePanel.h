#pragma once
// Hemisphere: what the probe point sees, drawn flat. The hemicube (Cohen & Greenberg 1985) over the
// point is shown as a Nusselt analog (the hemisphere projected straight down onto its base: the share
// of the disk a surface covers is its form factor) or as a fisheye (equidistant, or equisolid where
// area is solid angle), coloured by surface, by radiance, or by the delta form factors, with the
// theta/phi grid of d omega cells. For a target surface, the hemicube's solid angle and form factor
// stand beside the exact kernel's (Van Oosterom & Strackee, Lambert; with ray-cast visibility).
#include <cstdint>
#include <memory>
#include <optional>

#include "app/panels/HemicubeSession.h"
#include "app/panels/Panel.h"
#include "radiometry/hemicube/HemisphereProjection.h"
#include "radiometry/probe/Probe.h"
#include "render/hemicube/HemisphereImage.h"
#include "render/hemicube/ImageTexture.h"

namespace radiant {
class RayCaster;
}

namespace radiant::app {

class HemispherePanel final : public Panel {
public:
    explicit HemispherePanel(std::shared_ptr<HemicubeSession> session);
    ~HemispherePanel() override;

    [[nodiscard]] const char* title() const override { return "Hemisphere"; }
    [[nodiscard]] bool openByDefault() const override { return false; }
    void update() override;
    void draw() override;

    void setProjection(HemisphereProjection projection);
    void setColouring(render::HemisphereColouring colouring);
    void setTarget(std::size_t surface);
    /// The hemicube's and the exact readings of the target, when there is a point and a target.
    struct Comparison {
        SolidAngle hemicubeSolidAngle{};
        double hemicubeFormFactor = 0;
        double nusseltCoverage = 0;  ///< covered share of the Nusselt disk's pixels
        TargetReading exact;         ///< with visibility (Probe::target)
    };
    [[nodiscard]] const std::optional<Comparison>& comparison() const { return comparison_; }

private:
    struct Exact;
    void recolour();
    void remeasure();

    std::shared_ptr<HemicubeSession> session_;
    HemisphereProjection projection_ = HemisphereProjection::Nusselt;
    render::HemisphereImageOptions imageOptions_;
    std::optional<std::size_t> target_;
    std::unique_ptr<Exact> exact_;
    std::optional<render::ImageTexture> texture_;
    std::optional<HemisphereViewMap> map_;
    int mapResolution_ = 0;
    std::uint64_t colouredVersion_ = 0;
    std::uint64_t measuredCapture_ = 0;           ///< the geometric readings depend on the items alone
    std::optional<std::size_t> measuredTarget_;
    bool dirty_ = true;
    std::optional<Comparison> comparison_;
};

} // namespace radiant::app
