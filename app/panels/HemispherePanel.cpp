#include "app/panels/HemispherePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <glm/common.hpp>

#include "app/ui/HorizontalColourBar.h"
#include "app/ui/SidebarLayout.h"
#include "app/ui/WrappedText.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/hemicube/HemicubeGather.h"
#include "radiometry/hemisphere/HemisphericalCoordinates.h"
#include "render/ColourScale.h"
#include "render/SceneTriangles.h"

namespace radiant::app {
namespace {

constexpr int kViewPixels = 320;
constexpr int kOverlayPixels = 384;  ///< the dome's equidistant image: a projector shows the dome a few hundred pixels wide
constexpr double kOverlayUpAzimuth = std::numbers::pi / 2;
constexpr int kResolutions[] = {64, 128, 256, 512};

/// The azimuth (in the hemicube's frame) of the direction drawn upward: world up (+y) where the
/// normal is not vertical, else +z (deeper into the Cornell box, as its camera sees it).
double upAzimuth(const render::HemicubeFrame& frame) {
    glm::dvec3 up{0, 1, 0};
    if (std::abs(frame.normal().y) > 0.99) up = {0, 0, 1};
    const glm::dvec3 local = frame.toLocal(up);
    return std::atan2(local.y, local.x);
}

/// The delta form factor view's colour scale under the image: the heat ramp from 0 to the zenith
/// pixel's dF = dA / pi, ticks at 1-2-5 steps. dF is a form factor (dimensionless): the share of the
/// point's light that one hemicube pixel carries, cos(theta) d omega / pi.
void drawDeltaFormFactorScale(double zenithDeltaF, float width) {
    const float font = ImGui::GetFontSize();
    const float margin = font * 1.2f;  // room for half an end label either side
    const float barWidth = std::max(width - 2 * margin, font * 4);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 lo(origin.x + margin, origin.y + font * 0.2f), hi(lo.x + barWidth, lo.y + font * 0.8f);
    const auto colour = [](double t) {
        const glm::vec3 c = render::deltaFormFactorHeat(static_cast<float>(t));
        return ImGui::GetColorU32(ImVec4(static_cast<float>(render::linearToSrgb(c.x)), static_cast<float>(render::linearToSrgb(c.y)),
                                         static_cast<float>(render::linearToSrgb(c.z)), 1.0f));
    };
    drawHorizontalColourBar({lo, hi, 24, 0.4f, false}, colour, render::makeLegend(zenithDeltaF, false, 1));
    ImGui::Dummy(ImVec2(barWidth + 2 * margin, font * 2.3f));
    ui::wrappedText("delta F of one hemicube pixel (no unit: cos theta d omega / pi); the zenith pixel's is dA / pi = %.3g",
                       zenithDeltaF);
}

} // namespace

/// The exact route's machinery, rebuilt when the mesh changes; it casts through the scene's one ray
/// caster, the snapshot's.
struct HemispherePanel::Exact {
    std::uint64_t meshGeneration = 0;
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const PatchMesh> mesh;
    std::shared_ptr<const RayCaster> rays;  ///< kept alive for probe, which holds a plain pointer
    std::unique_ptr<Probe> probe;
};

HemispherePanel::HemispherePanel(std::shared_ptr<HemicubeSession> session) : session_(std::move(session)) {}
HemispherePanel::~HemispherePanel() = default;

void HemispherePanel::setProjection(HemisphereProjection projection) {
    projection_ = projection;
    map_.reset();
    dirty_ = true;
}
void HemispherePanel::setColouring(render::HemisphereColouring colouring) {
    imageOptions_.colouring = colouring;
    dirty_ = true;
}
void HemispherePanel::setTarget(std::size_t surface) {
    target_ = surface;
    dirty_ = true;
}

void HemispherePanel::setOverlayShown(bool shown) {
    overlayShown_ = shown;
    dirty_ = true;  // the dome's image is painted only while it shows
}

void HemispherePanel::update() {
    session_->update();
    if (!session_->ready()) {
        comparison_.reset();
        return;
    }
    const Snapshot& snapshot = session_->snapshot();
    if (!target_ || *target_ >= snapshot.scene->surfaces.size()) {
        // Default: the first emitter, the surface a lecture asks about.
        target_ = 0;
        for (std::size_t s = 0; s < snapshot.scene->surfaces.size(); ++s)
            if (snapshot.scene->materials[snapshot.scene->surfaces[s].material].emits()) {
                target_ = s;
                break;
            }
        dirty_ = true;
    }
    if (dirty_ || colouredVersion_ != session_->version()) {
        recolour();
        // Solid angles and form factors are geometry: a new solve step changes none of them.
        if (measuredCapture_ != session_->captureVersion() || measuredTarget_ != target_) {
            remeasure();
            measuredCapture_ = session_->captureVersion();
            measuredTarget_ = target_;
        }
        colouredVersion_ = session_->version();
        dirty_ = false;
    }
}

void HemispherePanel::recolour() {
    panelImageStale_ = true;
    imageOptions_.targetSurface = target_;  // the dome outlines it too
    const Snapshot& snapshot = session_->snapshot();
    // The dome's picture changes with the solve only when it shows radiance.
    const OverlayPainting painting{session_->captureVersion(), snapshot.scene.get(), imageOptions_.colouring, target_,
                                   imageOptions_.colouring == render::HemisphereColouring::Radiance ? session_->version()
                                                                                                   : 0};
    if (overlayShown_ && painting != overlayPainted_) {
        recolourOverlay();
        overlayPainted_ = painting;
    }
}

void HemispherePanel::recolourPanelImage() {
    panelImageStale_ = false;
    const render::HemicubeCapture& capture = session_->capture();
    const double up = upAzimuth(capture.frame);
    if (!map_ || map_->projection() != projection_ || mapResolution_ != capture.layout.resolution() ||
        mapUpAzimuth_ != up) {
        map_.emplace(capture.layout, projection_, kViewPixels, up);
        mapResolution_ = capture.layout.resolution();
        mapUpAzimuth_ = up;
    }
    const Snapshot& snapshot = session_->snapshot();
    std::vector<glm::vec3> colours;
    for (const Surface& surface : snapshot.scene->surfaces)
        colours.push_back(render::displayColour(snapshot.scene->materials[surface.material]));
    const std::span<const Rgb> radiosity = snapshot.radiosity.size() == snapshot.mesh->size()
                                               ? std::span<const Rgb>(snapshot.radiosity)
                                               : std::span<const Rgb>();
    const std::vector<std::uint8_t> rgba = render::hemisphereImage(*map_, capture, *snapshot.mesh, colours, radiosity, imageOptions_);
    if (!texture_) texture_.emplace();
    texture_->upload(kViewPixels, kViewPixels, rgba);
}

void HemispherePanel::recolourOverlay() {
    const render::HemicubeCapture& capture = session_->capture();
    const Snapshot& snapshot = session_->snapshot();
    if (!overlayMap_ || overlayMapResolution_ != capture.layout.resolution()) {
        overlayMap_.emplace(capture.layout, HemisphereProjection::Equidistant, kOverlayPixels, kOverlayUpAzimuth);
        overlayMapResolution_ = capture.layout.resolution();
    }
    if (sceneExtentMesh_ != snapshot.meshGeneration) {
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (const glm::dvec3& v : snapshot.mesh->vertices) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        const glm::dvec3 extent = hi - lo;
        sceneExtent_ = std::max({extent.x, extent.y, extent.z, 1e-6});
        sceneExtentMesh_ = snapshot.meshGeneration;
    }
    std::vector<glm::vec3> colours;
    for (const Surface& surface : snapshot.scene->surfaces)
        colours.push_back(render::displayColour(snapshot.scene->materials[surface.material]));
    render::HemisphereImageOptions look = imageOptions_;
    look.grid = false;       // the dome draws its own, a pixel wide at any size
    look.openSkyAlpha = 0;   // where the point sees nothing, the scene shows through
    const std::span<const Rgb> radiosity = snapshot.radiosity.size() == snapshot.mesh->size()
                                               ? std::span<const Rgb>(snapshot.radiosity)
                                               : std::span<const Rgb>();
    const std::vector<std::uint8_t> rgba =
        render::hemisphereImage(*overlayMap_, capture, *snapshot.mesh, colours, radiosity, look);
    if (!overlay_) overlay_.emplace();
    overlay_->setImage(kOverlayPixels, rgba, kOverlayUpAzimuth);
}

void HemispherePanel::drawOverlay(const render::Camera& camera, double aspect) {
    if (!overlayShown_ || !overlay_ || !session_->ready()) return;
    const render::HemicubeCapture& capture = session_->capture();
    const double radius = overlaySize_ * sceneExtent_;
    // Lifted a hair off the surface, so its rim does not fight the surface for depth.
    overlay_->setPlacement({capture.point + capture.normal * (2e-3 * radius), capture.frame, radius});
    overlay_->setStyle({overlayOpacity_, imageOptions_.grid});
    overlay_->draw(camera, aspect);
}

void HemispherePanel::remeasure() {
    const Snapshot& snapshot = session_->snapshot();
    if (!exact_ || exact_->meshGeneration != snapshot.meshGeneration) {
        exact_ = std::make_unique<Exact>();
        exact_->meshGeneration = snapshot.meshGeneration;
        exact_->scene = snapshot.scene;
        exact_->mesh = snapshot.mesh;
        exact_->rays = snapshot.rays;
        exact_->probe = std::make_unique<Probe>(*exact_->scene, *exact_->mesh, exact_->rays.get());
    }
    const HemicubePoint& point = *session_->point();
    Comparison c;
    const HemicubeSurfaceReading& reading = session_->gathered().surfaces[*target_];
    c.hemicubeSolidAngle = reading.solidAngle;
    c.hemicubeFormFactor = reading.formFactor;
    const render::HemicubeCapture& capture = session_->capture();
    const HemisphereViewMap nusselt(capture.layout, HemisphereProjection::Nusselt, kViewPixels);
    const Snapshot& s = snapshot;
    const std::size_t target = *target_;
    c.nusseltCoverage = diskCoverage(nusselt, capture.items, [&](std::uint32_t item) {
        return hemicubeItemIsFront(item) && s.mesh->patches[hemicubeItemPatch(item)].surface == target;
    });
    try {
        const SurfacePoint at = exact_->probe->locate(point.point, point.normal);
        c.exact = exact_->probe->target(at, point.normal, target);
        comparison_ = c;
    } catch (const std::exception&) {
        comparison_.reset();  // the point left the surface (a new mesh): wait for the next pick
    }
}

void HemispherePanel::draw() {
    if (!session_->ready()) {
        ui::wrappedText("Click a surface in the 3D view to stand a hemicube on it.");
        return;
    }
    if (panelImageStale_) recolourPanelImage();
    const Snapshot& snapshot = session_->snapshot();
    const render::HemicubeCapture& capture = session_->capture();

    int resolution = session_->resolution();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    if (ImGui::BeginCombo("hemicube pixels per side", std::to_string(resolution).c_str())) {
        for (const int r : kResolutions)
            if (ImGui::Selectable(std::to_string(r).c_str(), r == resolution)) session_->setResolution(r);
        ImGui::EndCombo();
    }
    int projection = static_cast<int>(projection_);
    bool changed = ImGui::RadioButton("Nusselt", &projection, 0);
    ui::sameLineIfFits(ui::radioButtonWidth("equidistant"));
    changed |= ImGui::RadioButton("equidistant", &projection, 1);
    ui::sameLineIfFits(ui::radioButtonWidth("equisolid"));
    changed |= ImGui::RadioButton("equisolid", &projection, 2);
    if (changed) setProjection(static_cast<HemisphereProjection>(projection));
    int colouring = static_cast<int>(imageOptions_.colouring);
    changed = ImGui::RadioButton("surfaces", &colouring, 0);
    ui::sameLineIfFits(ui::radioButtonWidth("radiance"));
    changed |= ImGui::RadioButton("radiance", &colouring, 1);
    ui::sameLineIfFits(ui::radioButtonWidth("delta F"));
    changed |= ImGui::RadioButton("delta F", &colouring, 2);
    if (changed) setColouring(static_cast<render::HemisphereColouring>(colouring));
    if (ImGui::Checkbox("theta/phi grid (15 / 30 deg)", &imageOptions_.grid)) dirty_ = true;
    bool dome = overlayShown_;
    if (ImGui::Checkbox("dome over the point in 3D (S)", &dome)) setOverlayShown(dome);
    if (overlayShown_) {
        float size = static_cast<float>(overlaySize_ * 100.0);
        ui::setNextWidthBesideLabel("dome radius, % of scene");
        if (ImGui::SliderFloat("dome radius, % of scene", &size, 5.0f, 40.0f, "%.0f %%")) overlaySize_ = size / 100.0;
        ui::setNextWidthBesideLabel("dome opacity");
        ImGui::SliderFloat("dome opacity", &overlayOpacity_, 0.2f, 1.0f, "%.2f");
    }
    if (ImGui::BeginCombo("target", snapshot.scene->surfaces[*target_].name.c_str())) {
        for (std::size_t s = 0; s < snapshot.scene->surfaces.size(); ++s)
            if (ImGui::Selectable(snapshot.scene->surfaces[s].name.c_str(), s == *target_)) setTarget(s);
        ImGui::EndCombo();
    }

    if (texture_) {
        const float side = std::min(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 20.0f);
        // ImGui's texture handle is the GL texture name (imgui_impl_opengl3's convention).
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_->id())), {side, side});  // NOLINT
        if (imageOptions_.colouring == render::HemisphereColouring::DeltaFormFactor)
            drawDeltaFormFactorScale(capture.layout.pixelArea() / std::numbers::pi, side);
    }
    ImGui::TextDisabled("%s", projectionName(projection_));
    ImGui::TextDisabled("hemicube %d x %d x 3: %.1f ms", capture.layout.width(), capture.layout.width(),
                        session_->lastRenderSeconds() * 1e3);
    if (projection_ == HemisphereProjection::Nusselt)
        ui::wrappedText("Share of the disk a surface covers = its form factor.");
    else if (projection_ == HemisphereProjection::Equisolid)
        ui::wrappedText("Equal-area: share of the disk = solid angle / 2 pi sr.");

    if (comparison_) {
        const Comparison& c = *comparison_;
        if (ImGui::BeginTable("##hemicube-vs-exact", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerH)) {
            ImGui::PushTextWrapPos(-1.0f);  // cells stay whole: the sidebar wraps prose, and a column fitted to wrapped text shrinks to a letter
            ImGui::TableSetupColumn(snapshot.scene->surfaces[*target_].name.c_str());
            ImGui::TableSetupColumn("hemicube");
            ImGui::TableSetupColumn("exact kernel");
            ImGui::TableHeadersRow();
            ImGui::TableNextRow();
            ImGui::TableNextColumn(); ImGui::TextUnformatted("solid angle");
            ImGui::TableNextColumn(); ImGui::Text("%.5f sr", c.hemicubeSolidAngle.value());
            ImGui::TableNextColumn(); ImGui::Text("%.5f sr", c.exact.solidAngle.value());
            ImGui::TableNextRow();
            ImGui::TableNextColumn(); ImGui::TextUnformatted("form factor");
            ImGui::TableNextColumn(); ImGui::Text("%.5f", c.hemicubeFormFactor);
            ImGui::TableNextColumn(); ImGui::Text("%.5f", c.exact.formFactor);
            ImGui::TableNextRow();
            ImGui::TableNextColumn(); ImGui::TextUnformatted("Nusselt disk share");
            ImGui::TableNextColumn(); ImGui::Text("%.5f", c.nusseltCoverage);
            ImGui::TableNextColumn(); ImGui::TextDisabled("(= F)");
            ImGui::PopTextWrapPos();
            ImGui::EndTable();
        }
        if (c.exact.formFactor > 0)
            ImGui::TextDisabled("hemicube F differs by %+.2f %%", 100.0 * (c.hemicubeFormFactor / c.exact.formFactor - 1.0));
    }
    const Rgb e = session_->gathered().irradiance.value();
    ui::wrappedText("E = sum B_j F_j = (%.4g, %.4g, %.4g) W/m^2", e.x, e.y, e.z);
    ImGui::TextDisabled("sum of delta F = %.5f (sky %.4f, backs %.4f)", session_->gathered().totalFormFactor,
                        session_->gathered().openFormFactor, session_->gathered().backFaceFormFactor);
}

} // namespace radiant::app
