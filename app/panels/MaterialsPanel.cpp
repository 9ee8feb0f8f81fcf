#include "app/panels/MaterialsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/ui/Colours.h"
#include "app/ui/WrappedText.h"

namespace radiant::app {
namespace {

const Material& materialOf(const Scene& scene, std::size_t surface) {
    return scene.materials.at(scene.surfaces.at(surface).material);
}

ImVec4 swatch(const Material& material) {
    // Emitters show their exitance's chromaticity, everything else its reflectance.
    Rgb c = material.reflectance;
    if (material.emits()) {
        const Rgb& e = material.exitance.value();
        c = e / std::max({e.x, e.y, e.z});
    }
    return {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z), 1.0f};
}

} // namespace

void MaterialsPanel::draw() {
    const Snapshot& snapshot = live_.snapshot();
    if (!snapshot.scene || snapshot.scene->surfaces.empty()) {
        ImGui::TextDisabled("no scene loaded");
        return;
    }
    const Scene& scene = *snapshot.scene;
    if (snapshot.meshGeneration != shownMesh_ || selected_ >= scene.surfaces.size()) {
        shownMesh_ = snapshot.meshGeneration;
        selected_ = 0;
        editing_ = false;
        refusal_.clear();
    }
    followProbe(snapshot);
    if (!editing_) loadFrom(scene);
    drawSurfaceList(scene);
    drawEditor(scene);
    ImGui::Spacing();
    drawUndoButtons();
    ImGui::SameLine();
    if (ImGui::Button("Reset materials")) {
        editing_ = false;
        refusal_.clear();
        resetMaterials(live_);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Every reflectance and exitance back to the scene's as loaded;\nthe solve starts again from B = E");
}

void MaterialsPanel::drawUndoButtons() {
    const MaterialEditHistory& history = live_.materialEdits;
    const auto button = [&](const char* label, bool enabled, const std::string& what, const char* keys) {
        ImGui::BeginDisabled(!enabled);
        const bool pressed = ImGui::Button(label);
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s: %s (%s)", label, enabled ? what.c_str() : "no material edit yet", keys);
        return pressed;
    };
    if (button("Undo", history.canUndo(), history.undoLabel(), "Ctrl+Z")) {
        editing_ = false;
        refusal_.clear();
        undo(live_);
    }
    ImGui::SameLine();
    if (button("Redo", history.canRedo(), history.redoLabel(), "Ctrl+Y")) {
        editing_ = false;
        refusal_.clear();
        redo(live_);
    }
}

void MaterialsPanel::followProbe(const Snapshot& snapshot) {
    if (!probed_) return;
    const std::optional<ProbePick> pick = probed_();
    if (!pick || pick->meshGeneration != snapshot.meshGeneration || pick->surface >= snapshot.scene->surfaces.size())
        return;
    // Only a new pick selects: a surface chosen in the list afterwards stays chosen.
    if (followed_ && followed_->point == pick->point && followed_->meshGeneration == pick->meshGeneration) return;
    followed_ = pick;
    if (selected_ == pick->surface) return;
    selected_ = pick->surface;
    editing_ = false;
    refusal_.clear();
    scrollToSelected_ = true;
}

void MaterialsPanel::drawSurfaceList(const Scene& scene) {
    ImGui::TextDisabled("Surfaces");
    const float rows = static_cast<float>(std::min<std::size_t>(scene.surfaces.size(), 10));
    const float height = rows * ImGui::GetTextLineHeightWithSpacing() + ImGui::GetStyle().FramePadding.y * 4.0f;
    if (ImGui::BeginListBox("##surfaces", {-1, height})) {
        for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
            ImGui::PushID(static_cast<int>(s));
            const Material& material = materialOf(scene, s);
            ImGui::ColorButton("##swatch", swatch(material), ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoBorder,
                               {ImGui::GetFontSize(), ImGui::GetFontSize()});
            ImGui::SameLine();
            const std::string label = scene.surfaces[s].name + (material.emits() ? "  (emitter)" : "");
            const bool clicked = ImGui::Selectable(label.c_str(), s == selected_);
            if (s == selected_ && scrollToSelected_) {
                ImGui::SetScrollHereY();
                scrollToSelected_ = false;
            }
            if (clicked) {
                selected_ = s;
                editing_ = false;
                refusal_.clear();
                loadFrom(scene);
            }
            ImGui::PopID();
        }
        ImGui::EndListBox();
    }
}

void MaterialsPanel::loadFrom(const Scene& scene) {
    const Material& material = materialOf(scene, selected_);
    for (int band = 0; band < 3; ++band) {
        reflectance_[band] = static_cast<float>(material.reflectance[band]);
        exitance_[band] = static_cast<float>(material.exitance.value()[band]);
    }
}

void MaterialsPanel::drawEditor(const Scene& scene) {
    ImGui::Spacing();
    ImGui::Text("%s", scene.surfaces[selected_].name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%.4f m\xC2\xB2", scene.surfaces[selected_].area());

    bool changed = false;
    bool committed = false;
    ImGui::TextDisabled("Reflectance (per band, 0 to %.3f)", kMaxReflectance);
    ImGui::SetNextItemWidth(-1);
    // The picker's own numbers are bounded to [0, 1]; typing a value of 1 or more is caught below.
    changed |= ImGui::ColorEdit3("##reflectance", reflectance_.data(), ImGuiColorEditFlags_Float);
    committed |= ImGui::IsItemDeactivatedAfterEdit();
    const float labelWidth = ImGui::CalcTextSize("W/m\xC2\xB2").x + ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::SetNextItemWidth(-labelWidth);
    changed |= ImGui::InputFloat3("##rhoNumbers", reflectance_.data(), "%.3f");
    committed |= ImGui::IsItemDeactivatedAfterEdit();

    ImGui::TextDisabled("Exitance (per band, >= 0)");
    ImGui::SetNextItemWidth(-labelWidth);
    changed |= ImGui::InputFloat3("##exitance", exitance_.data(), "%.2f");
    committed |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted("W/m\xC2\xB2");
    const Rgb e(exitance_[0], exitance_[1], exitance_[2]);
    ImGui::TextDisabled("Emitted power");
    ImGui::SameLine();
    const double area = scene.surfaces[selected_].area();
    ImGui::Text("%.3g, %.3g, %.3g W", e.x * area, e.y * area, e.z * area);

    if (changed) {
        const bool continuing = editing_;  // a drag or typing goes on: one plot segment for all of it
        editing_ = true;
        apply(continuing);
    }
    // Once the field is let go the panel follows the snapshot again (it holds what was applied).
    if (committed && refusal_.empty()) editing_ = false;
    if (!refusal_.empty()) {
        ui::wrappedTextColoured(theme::kWarningAmber, refusal_);
        if (ImGui::SmallButton("Revert")) {
            editing_ = false;
            refusal_.clear();
        }
    }
}

void MaterialsPanel::apply(bool continuesEdit) {
    const Rgb rho(reflectance_[0], reflectance_[1], reflectance_[2]);
    const Rgb e(exitance_[0], exitance_[1], exitance_[2]);
    refusal_ = submit(live_, selected_, rho, e, continuesEdit);
}

void MaterialsPanel::resetMaterials(LiveSolve& live) {
    const Snapshot& shown = live.snapshot();
    if (shown.scene) {
        live.materialEdits.follow(*shown.scene, shown.rays.get());
        live.materialEdits.recordReset(*shown.scene);
    }
    live.sendAndResume(command::ResetMaterials{});
}

namespace {

std::string sendHistoryStep(LiveSolve& live, bool undoing) {
    const Snapshot& shown = live.snapshot();
    if (!shown.scene) return {};
    MaterialEditHistory& history = live.materialEdits;
    history.follow(*shown.scene, shown.rays.get());
    const std::string what = undoing ? history.undoLabel() : history.redoLabel();
    const std::vector<SolverCommand> commands = undoing ? history.undo() : history.redo();
    if (commands.empty()) return {};
    // As an edit: a running or converged solve resumes from its solution, a paused one stays paused.
    const bool resume = live.resumesAfterChange();
    for (const SolverCommand& command : commands) live.send(command);
    if (resume) live.send(command::Run{});
    return (undoing ? "undid " : "redid ") + what + (undoing ? " (Ctrl+Y redoes it)" : "");
}

} // namespace

std::string MaterialsPanel::undo(LiveSolve& live) { return sendHistoryStep(live, true); }
std::string MaterialsPanel::redo(LiveSolve& live) { return sendHistoryStep(live, false); }

std::string MaterialsPanel::submit(LiveSolve& live, std::size_t surface, const Rgb& reflectance,
                                   const Rgb& exitanceW_m2, bool continuesEdit) {
    static constexpr const char* kBands[] = {"red", "green", "blue"};
    char message[200];
    for (int band = 0; band < 3; ++band) {
        if (!(reflectance[band] >= 0.0) || reflectance[band] > kMaxReflectance) {
            std::snprintf(message, sizeof message,
                          "Reflectance %s = %.3f is outside [0, %.3f]: a surface cannot reflect all the light "
                          "it receives. Not applied.",
                          kBands[band], reflectance[band], kMaxReflectance);
            return message;
        }
        if (!(exitanceW_m2[band] >= 0.0)) {
            std::snprintf(message, sizeof message, "Exitance %s = %.2f W/m\xC2\xB2 is negative. Not applied.",
                          kBands[band], exitanceW_m2[band]);
            return message;
        }
    }
    // Judged before sending: the snapshot is the one this frame shows.
    const Snapshot& shown = live.snapshot();
    if (shown.scene) {
        live.materialEdits.follow(*shown.scene, shown.rays.get());
        live.materialEdits.recordEdit(*shown.scene, surface, {reflectance, exitanceW_m2}, continuesEdit);
    }
    // A running or converged solve re-solves live, from its current solution (no new form factors).
    live.sendAndResume(command::SetMaterial{surface, reflectance, ExitanceRgb(exitanceW_m2), continuesEdit});
    return {};
}

} // namespace radiant::app
