#include "app/panels/ScenePanel.h"

#include <imgui.h>

#include <cmath>
#include <string>

#include "app/ui/Colours.h"
#include "app/ui/SidebarLayout.h"
#include "app/ui/WrappedText.h"
#include "radiometry/common/PatchAreaText.h"
#include "radiometry/common/Thousands.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/OpeningPatchArea.h"
#include "radiometry/solver/SolveDefaults.h"

namespace radiant::app {
namespace {

void sceneRow(const char* label, const char* format, auto... values) {
    ui::labelValueRow(label, 6.0f, format, values...);
}

} // namespace

ScenePanel::ScenePanel(LiveSolve& live, std::optional<double> maxPatchArea)
    : live_(live), fixedArea_(maxPatchArea), maxPatchArea_(maxPatchArea.value_or(kSolveDefaults.maxPatchArea)),
      sliderAreaCm2_(static_cast<float>(maxPatchArea_ * kCm2PerM2)), builtins_(builtinSceneNames()) {}

double ScenePanel::patchAreaFor(const Scene& scene) {
    if (fixedArea_) return *fixedArea_;
    OpeningArea opening = openingPatchArea(scene);
    maxPatchArea_ = opening.maxPatchArea;
    sliderAreaCm2_ = static_cast<float>(maxPatchArea_ * kCm2PerM2);
    openingReason_ = std::move(opening.reason);
    return maxPatchArea_;
}

void ScenePanel::open(const std::string& nameOrPath) {
    error_.clear();
    job_.start(nameOrPath);
}

void ScenePanel::update() {
    std::optional<SceneJobResult> result = job_.take();
    if (!result) return;
    if (!result->scene) {
        error_ = result->error;  // the previous scene stays
        return;
    }
    error_.clear();
    const double area = patchAreaFor(*result->scene);
    live_.send(command::LoadScene{std::move(result->scene), MeshingOptions{area}});
}

void ScenePanel::draw() {
    const Snapshot& snapshot = live_.snapshot();
    if (snapshot.scene) {
        const Scene& scene = *snapshot.scene;
        sceneRow("Scene", "%s", scene.name.c_str());
        sceneRow("Surfaces", "%zu  (%zu faces)", scene.surfaces.size(), scene.faceCount());
        const std::string patches = withThousands(snapshot.mesh ? snapshot.mesh->size() : std::size_t{0});
        if (snapshot.groups)
            sceneRow("Patches", "%s  (%s groups)", patches.c_str(), withThousands(snapshot.groups->size()).c_str());
        else
            sceneRow("Patches", "%s", patches.c_str());
        // Said where it changes the unknowns; an ungrouped scene says why under the box's tooltip.
        if (snapshot.groups) {
            ui::wrappedTextDisabled("Grouping %s", snapshot.groupingReason.c_str());
        }
        sceneRow("Area", "%.3f m\xC2\xB2", scene.totalArea());
        if (const std::size_t twoSided = scene.doubleSidedSurfaceCount(); twoSided > 0)
            ui::wrappedText("%zu double-sided surface%s: each side solved separately", twoSided, twoSided == 1 ? "" : "s");
        if (const std::size_t lights = scene.lights.size(); lights > 0) {
            ui::wrappedText("%zu glTF light%s (point, spot, sun): direct light a source on every patch", lights,
                               lights == 1 ? "" : "s");
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("KHR_lights_punctual, read from candela (lux for a sun) at 179 lm/W.\n"
                                  "Their direct irradiance, averaged over each patch with shadow rays,\n"
                                  "joins the emission: B = E + rho (H + sum F B).");
        }
    } else {
        ImGui::TextDisabled("no scene loaded");
    }

    ImGui::Spacing();
    ImGui::TextDisabled("Built-in scenes");
    const std::string current = snapshot.scene ? snapshot.scene->name : std::string();
    for (const std::string& name : builtins_)
        if (ImGui::Selectable(name.c_str(), name == current) && name != current) open(name);

    ImGui::Spacing();
    ImGui::TextDisabled("glTF file (or drop one on the window)");
    ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 4.0f);
    const bool entered = ImGui::InputTextWithHint("##path", "path/to/scene.gltf", path_.data(), path_.size(),
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || entered) && path_[0] != '\0') open(path_.data());

    drawMeshing();

    if (job_.running()) {
        ImGui::Spacing();
        ImGui::TextUnformatted(job_.what().c_str());
    }
    // A failed load, and a failed re-mesh (over the patch budget), both keep the previous scene.
    for (const std::string* message : {static_cast<const std::string*>(&error_), &snapshot.error})
        if (!message->empty()) ui::wrappedTextColoured(theme::kErrorRed, *message);
    // The loader's warnings travel with the scene, so they show however it was opened.
    if (snapshot.scene && !snapshot.scene->warnings.empty()) {
        for (const std::string& warning : snapshot.scene->warnings) ui::wrappedTextColoured(theme::kWarningAmber, warning);
    }
}

void ScenePanel::drawMeshing() {
    ImGui::Spacing();
    ImGui::TextDisabled("Meshing: largest patch area");
    ImGui::SetNextItemWidth(-1);
    // Logarithmic: useful sizes span from a fine 1 cm^2 to a coarse 0.25 m^2.
    ImGui::SliderFloat("##maxPatchArea", &sliderAreaCm2_, 1.0f, 2500.0f, "%.1f cm\xC2\xB2",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    const double requested = static_cast<double>(sliderAreaCm2_) / kCm2PerM2;
    const Snapshot& snapshot = live_.snapshot();
    if (ImGui::IsItemActive() && snapshot.scene) {
        const std::size_t estimate = estimatePatchCount(*snapshot.scene, MeshingOptions{requested});
        ImGui::SetTooltip("about %zu patches", estimate);
    }
    if (ImGui::IsItemDeactivatedAfterEdit() && std::abs(requested - maxPatchArea_) > 1e-12) {
        maxPatchArea_ = requested;
        openingReason_.clear();
        live_.sendAndResume(command::Remesh{MeshingOptions{requested}});
    }
    if (!openingReason_.empty()) {
        ui::wrappedTextDisabled("Opened at %s", openingReason_.c_str());
    }
    if (ImGui::Checkbox("Group patches", &groupPatches_))
        live_.sendAndResume(command::SetGrouping{groupPatches_ ? GroupingMode::Auto : GroupingMode::Off});
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
        ImGui::TextUnformatted("Adjacent patches of a smooth surface (a tessellated sphere, a rounded box) share one "
                               "radiosity, in groups of about the largest patch area, where that at least halves a "
                               "surface's patches: the unknowns follow the slider where the triangles are finer. "
                               "Unticked, every patch is an unknown. Progressive, Jacobi and Gauss-Seidel solve groups; "
                               "hierarchical does not.");
        if (const std::string& reason = live_.snapshot().groupingReason; !reason.empty())
            ui::wrappedText("Grouping %s", reason.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

} // namespace radiant::app
