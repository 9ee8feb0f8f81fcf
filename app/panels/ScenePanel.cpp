#include "app/panels/ScenePanel.h"

#include <imgui.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"

namespace radiant::app {
namespace {

constexpr double kCm2PerM2 = 1e4;
const ImVec4 kErrorRed{0.96f, 0.42f, 0.40f, 1.0f};
const ImVec4 kWarningAmber{0.95f, 0.75f, 0.35f, 1.0f};

void row(const char* label, const char* format, auto... values) {
    ImGui::TextDisabled("%s", label);
    ImGui::SameLine(ImGui::GetFontSize() * 6.0f);
    ImGui::Text(format, values...);
}

} // namespace

ScenePanel::ScenePanel(Install install, Scene initial, double maxPatchArea)
    : install_(std::move(install)), scene_(std::move(initial)), maxPatchArea_(maxPatchArea),
      sliderAreaCm2_(static_cast<float>(maxPatchArea * kCm2PerM2)), builtins_(builtinSceneNames()) {
    job_.start("meshing " + scene_.name, remesh(scene_, maxPatchArea_));
}

void ScenePanel::open(const std::string& nameOrPath) {
    error_.clear();
    job_.start("loading " + nameOrPath, loadAndMesh(nameOrPath, static_cast<double>(sliderAreaCm2_) / kCm2PerM2));
}

void ScenePanel::update() {
    std::optional<SceneJobResult> result = job_.take();
    if (!result) return;
    if (!result->scene) {
        error_ = result->error;  // the previous scene stays
        sliderAreaCm2_ = static_cast<float>(maxPatchArea_ * kCm2PerM2);
        return;
    }
    error_.clear();
    warnings_ = std::move(result->warnings);
    scene_ = std::move(*result->scene);
    patchCount_ = result->mesh.size();
    maxPatchArea_ = result->maxPatchArea;
    install_(scene_, result->mesh);
}

void ScenePanel::draw() {
    row("Scene", "%s", scene_.name.c_str());
    row("Surfaces", "%zu  (%zu faces)", scene_.surfaces.size(), scene_.faceCount());
    row("Patches", "%zu", patchCount_);
    row("Area", "%.3f m\xC2\xB2", scene_.totalArea());

    ImGui::Spacing();
    ImGui::TextDisabled("Built-in scenes");
    for (const std::string& name : builtins_)
        if (ImGui::Selectable(name.c_str(), name == scene_.name) && name != scene_.name) open(name);

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
        ImGui::ProgressBar(static_cast<float>(job_.fraction()), {-ImGui::GetFontSize() * 4.5f, 0});
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) job_.cancel();
    }
    if (!error_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorRed);
        ImGui::TextWrapped("%s", error_.c_str());
        ImGui::PopStyleColor();
    }
    if (!warnings_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kWarningAmber);
        for (const std::string& warning : warnings_) ImGui::TextWrapped("%s", warning.c_str());
        ImGui::PopStyleColor();
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
    if (ImGui::IsItemActive()) {
        const std::size_t estimate = estimatePatchCount(scene_, MeshingOptions{requested});
        ImGui::SetTooltip("about %zu patches", estimate);
    }
    if (ImGui::IsItemDeactivatedAfterEdit() && std::abs(requested - maxPatchArea_) > 1e-12) {
        error_.clear();
        job_.start("meshing " + scene_.name, remesh(scene_, requested));
    }
    ImGui::Checkbox("Show patch wireframe", &showWireframe_);
}

} // namespace radiant::app
