#include "app/LabComparison.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "app/SnapshotToRenderer.h"
#include "app/solver/SolveProgress.h"
#include "app/ui/ComparisonColours.h"
#include "app/ui/LegendOverlay.h"
#include "render/GlContext.h"

namespace radiant::app {
namespace {

/// A label box in the top-left corner of `view` (UI units): a title in `colour`, a line under it.
/// `room`: the share of the view's width it may take (the difference view's legend stands at the right).
void drawLabel(const render::Viewport& view, ImU32 colour, const std::string& title, const std::string& line,
               float room = 1.0f) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize();
    const float big = size * 1.25f;
    const float pad = size * 0.4f;
    const ImVec2 at{static_cast<float>(view.x) + size * 0.6f, static_cast<float>(view.y) + size * 0.6f};
    const float maxWidth = room * static_cast<float>(view.width) - 2.0f * size;
    const ImVec2 titleSize = font->CalcTextSizeA(big, maxWidth, maxWidth, title.c_str());
    const ImVec2 lineSize = font->CalcTextSizeA(size, maxWidth, maxWidth, line.c_str());
    const float width = std::max(titleSize.x, lineSize.x);
    draw->AddRectFilled({at.x - pad, at.y - pad}, {at.x + width + pad, at.y + titleSize.y + lineSize.y + pad},
                        IM_COL32(20, 22, 26, 200), size * 0.3f);
    draw->AddRectFilled({at.x - pad, at.y - pad}, {at.x - pad + size * 0.25f, at.y + titleSize.y + lineSize.y + pad}, colour);
    draw->AddText(font, big, {at.x + size * 0.2f, at.y}, colour, title.c_str(), nullptr, maxWidth);
    draw->AddText(font, size, {at.x + size * 0.2f, at.y + titleSize.y}, IM_COL32(235, 235, 235, 255), line.c_str(),
                  nullptr, maxWidth);
}

std::vector<render::Viewport> split(const render::Viewport& view) {
    const int left = view.width / 2;
    return {{view.x, view.y, std::max(1, left), view.height},
            {view.x + left, view.y, std::max(1, view.width - left), view.height}};
}

} // namespace

void LabComparison::cycle() {
    ComparisonSettings settings = live_.comparison();
    if (!live_.comparing()) {
        settings.view = ComparisonView::SideBySide;
        live_.setComparison(settings);
        live_.compare(true);
    } else if (settings.view == ComparisonView::SideBySide) {
        settings.view = ComparisonView::Difference;
        live_.setComparison(settings);
    } else {
        live_.compare(false);
    }
}

void LabComparison::stream(const render::DisplaySettings& display, const render::PatchRenderer& first) {
    if (!live_.comparing()) return;
    const Snapshot& b = *live_.secondCurrent;
    const bool showingDifference = live_.comparison().view == ComparisonView::Difference;
    if (b.scene && b.mesh && !showingDifference) {  // B's own colours are shown side by side only
        if (!second_) second_.emplace();
        streamSnapshotToRenderer(b, *second_, secondMaterials_);
        // One colour scale for both halves: false colour's automatic range is A's. Asked for only in
        // false colour: A's range sorts A's patches anew for each solution A takes (a tenth of the
        // main thread's time side by side while solving), and a range moved under B recolours B.
        render::DisplaySettings settings = display;
        if (settings.colourMode == render::ColourMode::FalseColour && settings.falseColourMaxW_m2 <= 0)
            settings.falseColourMaxW_m2 = static_cast<float>(first.legend().maxW_m2);
        second_->setSettings(settings);
    }
    if (!showingDifference) return;
    // While either side solves, the difference is redone at most kDifferenceHz times a second: each
    // redo recolours and uploads the finer mesh, and two running solvers publish twice as often as
    // one (the side-by-side view uploads only what changed on each side). At rest it is redone at once.
    const auto now = std::chrono::steady_clock::now();
    const bool solving = live_.current->running || b.running;
    if (!solving || differencer_.current().generation == 0 ||
        now - differenceComputedAt_ >= std::chrono::duration<double>(1.0 / kDifferenceHz)) {
        const std::uint64_t before = differencer_.current().generation;
        differencer_.update(*live_.current, b);
        if (differencer_.current().generation != before) differenceComputedAt_ = now;
    }
    const SolutionDifference& d = differencer_.current();
    if (!d.mesh) return;
    if (!difference_) difference_.emplace();
    if (d.mesh != differenceMesh_) {
        differenceMesh_ = d.mesh;
        difference_->setMesh(*d.scene, *d.mesh, ++differenceMeshKey_);
    }
    if (d.generation != differenceShown_) {
        // False colour maps the band total: a third of the ratio in each band shows the ratio itself.
        differenceValues_.resize(d.relative.size());
        for (std::size_t p = 0; p < d.relative.size(); ++p) differenceValues_[p] = Rgb(d.relative[p] / 3.0);
        difference_->setRadiosity(differenceValues_, d.generation);
        differenceShown_ = d.generation;
    }
    render::DisplaySettings settings = display;
    settings.colourMode = render::ColourMode::FalseColour;
    settings.logScale = true;
    settings.falseColourMaxW_m2 = kDifferenceTop;
    settings.shading = render::Shading::Flat;  // each patch's own difference, as computed
    // Where both agree the view is one flat colour: the patch edges keep the scene's shape readable
    // (and show what each value belongs to). On a fine mesh they are a few pixels apart, darken the
    // whole view and cost a derivative per pixel (a third of a frame on llvmpipe): none there.
    settings.wireframe = d.mesh->size() <= kMostPatchesWithEdges;
    settings.highlightShooter = false;
    settings.showImportance = false;
    settings.showLinks = false;
    difference_->setSettings(settings);
}

bool LabComparison::hidesFirst() const {
    return live_.comparing() && live_.comparison().view == ComparisonView::Difference && differencer_.current().mesh;
}

std::vector<render::Viewport> LabComparison::views(const render::Viewport& view) const {
    if (live_.comparing() && live_.comparison().view == ComparisonView::SideBySide) return split(view);
    return {view};
}

void LabComparison::draw(render::PatchRenderer& first, const render::DisplaySettings& display,
                         const render::Camera& camera, const render::Viewport& view, int framebufferHeight) {
    first.setSettings(display);
    const std::vector<render::Viewport> shown = views(view);
    if (hidesFirst() && difference_ && differenceMesh_) {
        // A is not shown: its colours wait for the view that shows it (recolouring both meshes every
        // step cost the difference view a quarter more main-thread time than side by side).
        difference_->prepare();
        difference_->draw(camera, view.aspect());
        return;
    }
    first.prepare();
    if (shown.size() == 2) {
        render::useViewport(framebufferHeight, shown[1]);
        if (second_) {
            second_->prepare();
            second_->draw(camera, shown[1].aspect());
        }
        render::useViewport(framebufferHeight, shown[0]);
    }
    first.draw(camera, shown[0].aspect());
}

bool LabComparison::drawOverlays(const render::Viewport& viewInUiUnits) const {
    if (!live_.comparing()) return false;
    const Snapshot& a = *live_.current;
    const Snapshot& b = *live_.secondCurrent;
    const ComparisonSettings& settings = live_.comparison();
    const std::string labelA = comparisonLabel('A', a.method, 1.0);
    const std::string labelB = comparisonLabel('B', b.method, settings.patchAreaScale);
    if (settings.view == ComparisonView::SideBySide) {
        const std::vector<render::Viewport> halves = split(viewInUiUnits);
        drawLabel(halves[0], theme::kSideA, labelA, progressLine(a, longWorkDone(live_.thread)));
        drawLabel(halves[1], theme::kSideB, labelB, progressLine(b, longWorkDone(*live_.second)));
        const auto x = static_cast<float>(halves[1].x);
        ImGui::GetBackgroundDrawList()->AddLine({x, static_cast<float>(viewInUiUnits.y)},
                                                {x, static_cast<float>(viewInUiUnits.y + viewInUiUnits.height)},
                                                IM_COL32(200, 200, 200, 255), std::max(2.0f, ImGui::GetFontSize() * 0.12f));
        return false;
    }
    const SolutionDifference& d = differencer_.current();
    static_assert(kDarkShare == 0.01, "the legend, this label and the Difference and probe tooltips say 1%");
    char line[480];
    if (d.mesh) {
        const std::size_t surface = d.mesh->patches.at(d.largestPatch).surface;
        // Where B is below the dark floor on both sides the ratio is taken to the floor: say so, and
        // how many patches that is, or a reader takes 100% at a patch nobody lights for a wrong solver.
        std::snprintf(line, sizeof line,
                      "mean %.3g%%, largest %.3g%% (%s)\non %s's mesh (%zu patches)\n"
                      "B under 1%% of the mean, %.2g W/m\xC2\xB2 R+G+B,\ncounts as that: %zu patches dark in both",
                      100 * d.meanRelative, 100 * d.maxRelative, d.scene->surfaces.at(surface).name.c_str(),
                      d.onFirst ? "A" : "B", d.mesh->size(), d.darkFloor, d.darkPatches);
    } else
        std::snprintf(line, sizeof line, "waiting for both to step (A: %s; B: %s)",
                      progressLine(a, longWorkDone(live_.thread)).c_str(), progressLine(b, longWorkDone(*live_.second)).c_str());
    drawLabel(viewInUiUnits, IM_COL32(235, 235, 235, 255), "Difference |B_A - B_B| / B",
              labelA + "  vs  " + labelB + "\n" + line, 0.6f);
    render::ColourLegend difference = render::makeLegend(kDifferenceTop, true, render::DisplaySettings::kLogDecades);
    difference.quantity = "|B_A - B_B| / max(B, 1% mean)";
    difference.unit = "ratio (0.01 = 1%)";
    drawLegendOverlay(difference, viewInUiUnits);
    return true;
}

void LabComparison::release() {
    second_.reset();
    difference_.reset();
}

} // namespace radiant::app
