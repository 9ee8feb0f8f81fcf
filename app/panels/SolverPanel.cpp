#include "app/panels/SolverPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "app/solver/MethodLabel.h"
#include "app/ui/Colours.h"
#include "app/ui/SidebarLayout.h"
#include "app/ui/WrappedText.h"

namespace radiant::app {
namespace {

bool shoots(SolverMethod method) { return methodInfo(method).traits.shoots; }
bool links(SolverMethod method) { return methodInfo(method).traits.links; }

void solverRow(const char* label, const char* format, auto... values) {
    ui::labelValueRow(label, 7.0f, format, values...);
}

double totalWatts(const PowerRgb& power) {
    const Rgb& p = power.value();
    return p.x + p.y + p.z;
}

} // namespace

void SolverPanel::draw() {
    const Snapshot& snapshot = live_.snapshot();
    drawControls(snapshot);
    drawComparison();
    drawStats(snapshot);
    convergence_.draw(snapshot, live_.secondCurrent.get());
    drawStepTimes(snapshot);
}

void SolverPanel::drawControls(const Snapshot& snapshot) {
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##method", methodLabel(snapshot.method))) {
        for (const SolverMethodInfo& method : solverMethods())
            if (ImGui::Selectable(method.label.data(), method.method == snapshot.method) &&
                method.method != snapshot.method)
                live_.send(command::SetMethod{method.method});
        ImGui::EndCombo();
    }
    if (!snapshot.methodReason.empty()) {  // chosen by the scene's size until the user picks one
        ui::wrappedTextDisabled("Default for this mesh: %s", snapshot.methodReason.c_str());
    }
    if (snapshot.methodTakesNoGroups) {  // a picked hierarchical solves the patches the Scene panel would group
        const std::string_view reason = snapshot.groupingReason;
        const std::string_view why = reason.starts_with("off: ") ? reason.substr(5) : reason;
        ui::wrappedTextDisabled("Patches not grouped: %.*s", static_cast<int>(why.size()), why.data());
    }

    const float buttonWidth = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
    if (ImGui::Button(live_.running() ? "Pause" : "Run", {buttonWidth, 0}))
        live_.send(live_.running() ? SolverCommand{command::Pause{}} : SolverCommand{command::Run{}});
    ImGui::SameLine();
    if (ImGui::Button("Step", {buttonWidth, 0})) live_.send(command::Step{1});
    ImGui::SameLine();
    if (ImGui::Button("Reset", {buttonWidth, 0})) live_.send(command::Reset{});

    char label[32];
    std::snprintf(label, sizeof label, "Step %d", stepCount_);
    if (ImGui::Button(label, {buttonWidth, 0})) live_.send(command::Step{static_cast<std::size_t>(stepCount_)});
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputInt("##stepCount", &stepCount_, 1, 10)) stepCount_ = std::clamp(stepCount_, 1, 100000);

    if (!editingTolerance_) toleranceExponent_ = static_cast<float>(std::log10(snapshot.tolerance));
    const float textWidth = ImGui::CalcTextSize("Tolerance").x + ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::SetNextItemWidth(-textWidth);
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.0e", std::pow(10.0, static_cast<double>(toleranceExponent_)));
    ImGui::SliderFloat("Tolerance", &toleranceExponent_, -8.0f, -1.0f, shown);
    editingTolerance_ = ImGui::IsItemActive();
    if (ImGui::IsItemDeactivatedAfterEdit())
        live_.send(command::SetTolerance{std::pow(10.0, static_cast<double>(toleranceExponent_))});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Run stops when the method's convergence measure (the row below the iteration) falls "
                          "below this");

    if (!links(snapshot.method)) return;
    if (!editingLinkTolerance_) linkToleranceExponent_ = static_cast<float>(std::log10(snapshot.linkTolerance));
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Links").x - ImGui::GetStyle().ItemInnerSpacing.x);
    std::snprintf(shown, sizeof shown, "%.0e", std::pow(10.0, static_cast<double>(linkToleranceExponent_)));
    ImGui::SliderFloat("Links", &linkToleranceExponent_, -7.0f, -2.0f, shown);
    editingLinkTolerance_ = ImGui::IsItemActive();
    if (ImGui::IsItemDeactivatedAfterEdit())
        live_.send(command::SetLinkTolerance{std::pow(10.0, static_cast<double>(linkToleranceExponent_))});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Link tolerance: a link is refined while the radiosity error it may leave exceeds this\n"
                          "fraction of the emitted power. Smaller is more accurate and slower; changing it\n"
                          "rebuilds the links.");
}

void SolverPanel::drawComparison() {
    bool comparing = live_.comparing();
    if (ImGui::Checkbox("Compare two methods (V)", &comparing)) live_.compare(comparing);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Solves the same scene a second way (B) on a second solver thread: the 3D view splits\n"
                          "in two halves with one camera, the plot shows both curves, the probe reads both.\n"
                          "Turning it on restarts A, so both start from B = E together.");
    if (!comparing) return;
    ComparisonSettings settings = live_.comparison();
    const float labelWidth = ImGui::CalcTextSize("B method").x + ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::SetNextItemWidth(-labelWidth);
    if (ImGui::BeginCombo("B method", methodLabel(settings.method))) {
        for (const SolverMethodInfo& method : solverMethods())
            if (ImGui::Selectable(method.label.data(), method.method == settings.method)) settings.method = method.method;
        ImGui::EndCombo();
    }
    const char* meshShown = kPatchAreaChoices[0].label;
    for (const PatchAreaChoice& choice : kPatchAreaChoices)
        if (choice.scale == settings.patchAreaScale) meshShown = choice.label;
    ImGui::SetNextItemWidth(-labelWidth);
    if (ImGui::BeginCombo("B mesh", meshShown)) {
        for (const PatchAreaChoice& choice : kPatchAreaChoices)
            if (ImGui::Selectable(choice.label, choice.scale == settings.patchAreaScale)) settings.patchAreaScale = choice.scale;
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("B's largest patch area against A's (the Scene panel's meshing slider): one method at two\n"
                          "meshings shows the discretisation error; the difference view maps the finer onto the coarser");
    int view = settings.view == ComparisonView::SideBySide ? 0 : 1;
    ImGui::RadioButton("Side by side", &view, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Difference", &view, 1);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Per patch of the finer mesh: |B_A - B_B| / B, the relative difference of the two\n"
                          "solutions' radiosity (R+G+B), in false colour on a log scale. B is the larger of the\n"
                          "two, or 1%% of the scene's mean radiosity where both are darker than that: a patch\n"
                          "no method should light (floor under a block) reads its stray light against the\n"
                          "scene's scale, not 100%%");
    settings.view = view == 0 ? ComparisonView::SideBySide : ComparisonView::Difference;
    if (!(settings == live_.comparison())) live_.setComparison(settings);
    ImGui::Separator();
}

void SolverPanel::drawStats(const Snapshot& snapshot) {
    ImGui::Spacing();
    const IterationStats& stats = snapshot.stats;
    const bool converged = !snapshot.running && stats.iteration > 0 && stats.residual < snapshot.tolerance;
    solverRow("State", "%s", snapshot.running ? "running" : converged ? "converged" : stats.iteration > 0 ? "paused" : "ready");
    solverRow("Iteration", "%zu", stats.iteration);
    solverRow(shoots(snapshot.method) ? "Unshot / emitted" : links(snapshot.method) ? "Sweep change" : "Residual", "%.3e",
        stats.iteration > 0 ? stats.residual : 1.0);
    if (ImGui::IsItemHovered()) {
        const std::string_view meaning = methodInfo(snapshot.method).residual;
        ImGui::SetTooltip("%.*s (dimensionless; Run stops below the tolerance)", static_cast<int>(meaning.size()),
                          meaning.data());
    }
    if (shoots(snapshot.method)) {
        solverRow("Unshot power", "%.4g W", totalWatts(stats.unshotPower));
        if (stats.shooter >= 0 && snapshot.mesh && snapshot.scene &&
            static_cast<std::size_t>(stats.shooter) < snapshot.mesh->patches.size()) {
            const std::size_t surface = snapshot.mesh->patches[static_cast<std::size_t>(stats.shooter)].surface;
            solverRow("Last shooter", "%s", snapshot.scene->surfaces.at(surface).name.c_str());
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("Patch %lld shot its unshot power last (outlined in the 3D view)",
                                  static_cast<long long>(stats.shooter));
        }
    }
    if (links(snapshot.method)) {
        // Refinement replaces a link by its children's: the count moves by created minus removed.
        const std::size_t before = snapshot.history.size() >= 2 ? snapshot.history[snapshot.history.size() - 2].links : 0;
        const long long net = static_cast<long long>(stats.links) - static_cast<long long>(before);
        const long long removed = std::max(0LL, static_cast<long long>(stats.linksRefined) - net);
        solverRow("Links", "%zu (%+lld this step)", stats.links, snapshot.history.size() >= 2 ? net : 0LL);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("This step created %zu links by refinement and removed the %lld they replaced",
                              stats.linksRefined, removed);
    }
    solverRow("Step time", "%.3f ms", stats.seconds * 1e3);
    if (!snapshot.error.empty()) ui::wrappedTextColoured(theme::kErrorRed, snapshot.error);
}

void SolverPanel::drawStepTimes(const Snapshot& snapshot) {
    const SolveHistory& history = snapshot.history;
    if (history.empty()) return;
    // Long runs (thousands of shots) are thinned to what the plot's width can show.
    const std::size_t stride = std::max<std::size_t>(1, history.size() / 512);
    plotValues_.clear();
    for (std::size_t i = 0; i < history.size(); i += stride)
        plotValues_.push_back(static_cast<float>(history[i].seconds * 1e3));
    const auto [lo, hi] = std::minmax_element(plotValues_.begin(), plotValues_.end());
    ImGui::Spacing();
    ImGui::TextDisabled("time per iteration (ms), this run");
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.3g .. %.3g ms", static_cast<double>(*lo), static_cast<double>(*hi));
    ImGui::PlotLines("##time", plotValues_.data(), static_cast<int>(plotValues_.size()), 0, overlay, *lo,
                     *hi > *lo ? *hi : *lo + 1.0f, {ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 3.0f});
}

} // namespace radiant::app
