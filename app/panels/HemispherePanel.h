#pragma once
// Hemisphere: what the probe point sees, drawn flat. The hemicube (Cohen & Greenberg 1985) over the
// point is shown as a Nusselt analog (the hemisphere projected straight down onto its base: the share
// of the disk a surface covers is its form factor) or as a fisheye (equidistant, or equisolid where
// area is solid angle), coloured by surface, by radiance, or by the delta form factors, with the
// theta/phi grid of d omega cells. For a target surface, the hemicube's solid angle and form factor
// stand beside the exact kernel's (Van Oosterom & Strackee, Lambert; with ray-cast visibility).
// In the 3D view the same sky is painted on a dome standing on the point (render/hemisphere/).
#include <cstdint>
#include <memory>
#include <optional>

#include "app/panels/HemicubeSession.h"
#include "app/panels/Panel.h"
#include "radiometry/hemicube/HemisphereProjection.h"
#include "radiometry/probe/Probe.h"
#include "render/hemicube/HemisphereImage.h"
#include "render/hemicube/ImageTexture.h"
#include "render/hemisphere/HemisphereOverlay.h"

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

    /// The dome over the probe point in the 3D view (on by default; key S in the lab).
    void setOverlayShown(bool shown);
    [[nodiscard]] bool overlayShown() const { return overlayShown_; }
    /// The dome's radius as a fraction of the scene's largest extent (0.15 by default).
    void setOverlaySize(double fractionOfScene) { overlaySize_ = fractionOfScene; }
    /// Draws the dome after the scene, into the 3D view's framebuffer and viewport; nothing when it
    /// is hidden or there is no point yet.
    void drawOverlay(const render::Camera& camera, double aspect);

private:
    struct Exact;
    /// Repaints what changed: the dome at once (the 3D view shows it with the panel closed), the
    /// panel's own image only when the panel is drawn (panelImageStale_).
    void recolour();
    void recolourPanelImage();
    void remeasure();

    std::shared_ptr<HemicubeSession> session_;
    HemisphereProjection projection_ = HemisphereProjection::Nusselt;
    render::HemisphereImageOptions imageOptions_;
    std::optional<std::size_t> target_;
    std::unique_ptr<Exact> exact_;
    std::optional<render::ImageTexture> texture_;
    std::optional<HemisphereViewMap> map_;
    int mapResolution_ = 0;
    double mapUpAzimuth_ = 0;
    std::uint64_t colouredVersion_ = 0;
    std::uint64_t measuredCapture_ = 0;           ///< the geometric readings depend on the items alone
    std::optional<std::size_t> measuredTarget_;
    bool dirty_ = true;
    bool panelImageStale_ = true;  ///< the panel's image waits for draw(): closed, it costs nothing
    std::optional<Comparison> comparison_;

    void recolourOverlay();
    /// What the dome's picture was painted from.
    struct OverlayPainting {
        std::uint64_t capture = 0;
        const Scene* scene = nullptr;  ///< a material edit makes a new scene: new surface colours
        render::HemisphereColouring colouring = render::HemisphereColouring::Surfaces;
        std::optional<std::size_t> target;
        std::uint64_t solution = 0;  ///< the session's version, for radiance; 0 otherwise
        bool operator==(const OverlayPainting&) const = default;
    };
    OverlayPainting overlayPainted_;
    bool overlayShown_ = true;
    double overlaySize_ = 0.15;
    float overlayOpacity_ = 0.85f;
    std::optional<render::HemisphereOverlay> overlay_;
    std::optional<HemisphereViewMap> overlayMap_;  ///< equidistant, image up at azimuth pi/2
    int overlayMapResolution_ = 0;
    double sceneExtent_ = 1;                        ///< m, the mesh's largest bounding-box side
    std::uint64_t sceneExtentMesh_ = 0;
};

} // namespace radiant::app
