#include "app/panels/IntegralsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "app/ui/SidebarLayout.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"

namespace radiant::app {
namespace {

const char* integrandLabel(HemisphereIntegrand i) {
    switch (i) {
    case HemisphereIntegrand::SolidAngle: return "d omega";
    case HemisphereIntegrand::ProjectedSolidAngle: return "cos theta d omega";
    case HemisphereIntegrand::Irradiance: return "L cos theta d omega";
    }
    return "?";
}

const ImU32 kDisk = IM_COL32(40, 44, 52, 255);
const ImU32 kRim = IM_COL32(150, 150, 160, 255);
const ImU32 kSample = IM_COL32(255, 200, 40, 200);
const ImU32 kNewest = IM_COL32(255, 90, 60, 255);
const ImU32 kErrorColour = IM_COL32(90, 200, 255, 255);
const ImU32 kReference = IM_COL32(220, 220, 220, 160);
const ImU32 kRiemann = IM_COL32(120, 220, 120, 255);

} // namespace

IntegralsPanel::IntegralsPanel(std::shared_ptr<HemicubeSession> session) : session_(std::move(session)) { rebuild(); }

void IntegralsPanel::select(HemisphereIntegrand integrand, const IntegralSettings& settings) {
    integrand_ = integrand;
    settings_ = settings;
    rebuild();
}

void IntegralsPanel::rebuild() {
    running_ = false;
    const bool irradiance = integrand_ == HemisphereIntegrand::Irradiance && session_ && session_->ready();
    if (integrand_ == HemisphereIntegrand::Irradiance && !irradiance) integrand_ = HemisphereIntegrand::ProjectedSolidAngle;
    std::function<double(const glm::dvec3&)> f;
    double exact = 0;
    switch (integrand_) {
    case HemisphereIntegrand::SolidAngle:
        f = [](const glm::dvec3&) { return 1.0; };
        exact = kHemisphereSolidAngle.value();
        break;
    case HemisphereIntegrand::ProjectedSolidAngle:
        f = [](const glm::dvec3& d) { return d.z; };
        exact = kHemisphereProjectedSolidAngle.value();
        break;
    case HemisphereIntegrand::Irradiance: {
        // The reference is the hemicube's own quadrature, sum_j B_j F_j: the same L, integrated finely.
        const int band = band_;
        std::shared_ptr<HemicubeSession> session = session_;
        exact = session->gathered().irradiance.value()[band];
        f = [session, band](const glm::dvec3& d) { return session->radianceToward(d)[band] * d.z; };
        break;
    }
    }
    run_ = std::make_unique<HemisphereIntegralRun>(f, exact, settings_);
    // A Riemann sum is only an estimate once complete, so its convergence is shown across grids:
    // the error of each full sum against its cell count N = 4 t^2 (slope -1: O(h^2) = O(1/N)).
    riemannSeries_.clear();
    if (settings_.method == IntegralMethod::Riemann)
        for (const int t : {1, 2, 3, 4, 6, 8, 11, 16, 23, 32, 45, 64}) {
            IntegralSettings grid = settings_;
            grid.thetaCells = t;
            HemisphereIntegralRun full(f, exact, grid);
            full.step(full.total());
            riemannSeries_.push_back(full.errorHistory().back());
        }
}

void IntegralsPanel::update() {
    if (running_ && !run_->step(static_cast<std::size_t>(samplesPerFrame_))) running_ = false;
}

void IntegralsPanel::draw() {
    int integrand = static_cast<int>(integrand_);
    bool changed = false;
    changed |= ImGui::RadioButton("d omega", &integrand, 0);
    ui::sameLineIfFits(ui::radioButtonWidth("cos d omega"));
    changed |= ImGui::RadioButton("cos d omega", &integrand, 1);
    ui::sameLineIfFits(ui::radioButtonWidth("L cos d omega"));
    const bool haveHemicube = session_ && session_->ready();
    ImGui::BeginDisabled(!haveHemicube);
    changed |= ImGui::RadioButton("L cos d omega", &integrand, 2);
    ImGui::EndDisabled();
    if (!haveHemicube && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Pick a probe point: L comes from the hemicube over it");
    if (integrand == 2) {
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
        changed |= ImGui::Combo("band", &band_, "red\0green\0blue\0");
    }
    int method = static_cast<int>(settings_.method);
    changed |= ImGui::RadioButton("Riemann", &method, 0);
    ui::sameLineIfFits(ui::radioButtonWidth("uniform MC"));
    changed |= ImGui::RadioButton("uniform MC", &method, 1);
    ui::sameLineIfFits(ui::radioButtonWidth("cosine MC"));
    changed |= ImGui::RadioButton("cosine MC", &method, 2);
    if (method == 0)
        changed |= ImGui::SliderInt("theta cells", &settings_.thetaCells, 2, 64);
    ImGui::SliderInt("samples / frame", &samplesPerFrame_, 1, 500, "%d", ImGuiSliderFlags_Logarithmic);
    if (changed) {
        integrand_ = static_cast<HemisphereIntegrand>(integrand);
        settings_.method = static_cast<IntegralMethod>(method);
        rebuild();
    }
    if (ImGui::Button(running_ ? "Pause" : "Run")) running_ = !running_;
    ImGui::SameLine();
    if (ImGui::Button("Step")) run_->step(1);
    ImGui::SameLine();
    if (ImGui::Button("Reset")) rebuild();

    const HemisphereEstimate e = run_->estimate();
    const char* unit = integrand_ == HemisphereIntegrand::Irradiance ? "W/m^2" : "sr";
    ImGui::Text("integral of %s", integrandLabel(integrand_));
    ImGui::Text("N = %zu of %zu", run_->taken(), run_->total());
    ImGui::Text("estimate %.6f %s", e.value, unit);
    if (infiniteVariance()) {
        ImGui::TextDisabled("no error bar: infinite variance");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Cosine-weighted samples of the plain solid angle weigh each direction by pi / cos theta:\n"
                              "the estimate still converges to 2 pi, but its variance integral, pi times the\n"
                              "integral of d omega / cos theta, diverges at the horizon, so s / sqrt(N) means nothing.");
    } else if (run_->settings().method != IntegralMethod::Riemann) {
        ImGui::SameLine(), ImGui::TextDisabled("+- %.2g", e.standardError);
    }
    ImGui::Text("exact    %.6f %s%s", run_->exact(), unit,
                integrand_ == HemisphereIntegrand::Irradiance ? " (hemicube sum B_j F_j)" : "");
    if (run_->taken() > 0) ImGui::Text("error    %.3g %s (%.3g %%)", e.value - run_->exact(), unit,
                                       run_->exact() != 0 ? 100.0 * (e.value / run_->exact() - 1.0) : 0.0);

    const float width = std::min(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 20.0f);
    drawDiagram(width * 0.8f);
    drawErrorPlot(width, width * 0.6f);
}

void IntegralsPanel::drawDiagram(float side) const {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float radius = side * 0.5f;
    const ImVec2 centre{origin.x + radius, origin.y + radius};
    draw->AddCircleFilled(centre, radius, kDisk, 64);
    for (int k = 1; k <= 5; ++k)  // theta = 15 .. 75 degrees, projected as the Nusselt disk shows them
        draw->AddCircle(centre, radius * static_cast<float>(std::sin(k * std::numbers::pi / 12)), IM_COL32(80, 84, 96, 255), 48);
    draw->AddCircle(centre, radius, kRim, 64, 1.5f);
    const std::deque<glm::dvec3>& samples = run_->recentDirections();
    // Straight down onto the base disk (Nusselt): cosine-weighted samples fill it evenly.
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const glm::dvec3& d = samples[i];
        const ImVec2 p{centre.x + radius * static_cast<float>(d.x), centre.y - radius * static_cast<float>(d.y)};
        if (i + 1 == samples.size())
            draw->AddCircleFilled(p, 3.5f, kNewest);
        else
            draw->AddRectFilled({p.x - 0.8f, p.y - 0.8f}, {p.x + 0.8f, p.y + 0.8f}, kSample);
    }
    ImGui::Dummy({side, side});
    ImGui::TextDisabled("samples seen from above (radius = sin theta)");
}

void IntegralsPanel::drawErrorPlot(float width, float height) const {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float left = ImGui::GetFontSize() * 2.5f, bottom = ImGui::GetFontSize() * 1.2f;
    const ImVec2 lo{origin.x + left, origin.y + height - bottom}, hi{origin.x + width, origin.y};
    draw->AddRectFilled({lo.x, hi.y}, {hi.x, lo.y}, kDisk);
    // Decades: N from 1 to 1e5, relative error from 1e-5 to 10.
    constexpr double nDecades = 5, errorLow = -5, errorHigh = 1;
    const auto toScreen = [&](double n, double relativeError) {
        const double u = std::log10(std::max(n, 1.0)) / nDecades;
        const double v = (std::log10(std::max(relativeError, 1e-12)) - errorLow) / (errorHigh - errorLow);
        return ImVec2{lo.x + static_cast<float>(std::clamp(u, 0.0, 1.0)) * (hi.x - lo.x),
                      lo.y - static_cast<float>(std::clamp(v, 0.0, 1.0)) * (lo.y - hi.y)};
    };
    for (int d = 0; d <= static_cast<int>(nDecades); ++d) {
        const ImVec2 p = toScreen(std::pow(10.0, d), 1e-5);
        draw->AddLine({p.x, lo.y}, {p.x, hi.y}, IM_COL32(70, 74, 86, 255));
        char label[8];
        std::snprintf(label, sizeof label, "1e%d", d);
        draw->AddText({p.x - 6, lo.y + 2}, IM_COL32(160, 160, 170, 255), label);
    }
    for (int d = static_cast<int>(errorLow); d <= static_cast<int>(errorHigh); ++d) {
        const ImVec2 p = toScreen(1, std::pow(10.0, d));
        draw->AddLine({lo.x, p.y}, {hi.x, p.y}, IM_COL32(70, 74, 86, 255));
        char label[8];
        std::snprintf(label, sizeof label, "1e%d", d);
        draw->AddText({origin.x, p.y - 7}, IM_COL32(160, 160, 170, 255), label);
    }
    const std::vector<ErrorPoint>& history = run_->errorHistory();
    const double scale = std::abs(run_->exact()) > 0 ? std::abs(run_->exact()) : 1.0;
    // The 1/sqrt(N) line through the latest Monte Carlo error estimate: s / sqrt(N) for every N.
    if (!history.empty() && history.back().standardError > 0 && !infiniteVariance()) {
        const double sigma = history.back().standardError * std::sqrt(static_cast<double>(history.back().samples));
        draw->AddLine(toScreen(1, sigma / scale), toScreen(1e5, sigma / std::sqrt(1e5) / scale), kReference, 1.5f);
    }
    for (std::size_t i = 1; i < history.size(); ++i)
        draw->AddLine(toScreen(static_cast<double>(history[i - 1].samples), history[i - 1].absoluteError / scale),
                      toScreen(static_cast<double>(history[i].samples), history[i].absoluteError / scale), kErrorColour, 1.5f);
    for (const ErrorPoint& p : history)
        draw->AddCircleFilled(toScreen(static_cast<double>(p.samples), p.absoluteError / scale), 2.0f, kErrorColour);
    for (std::size_t i = 0; i < riemannSeries_.size(); ++i) {
        const ImVec2 p = toScreen(static_cast<double>(riemannSeries_[i].samples), riemannSeries_[i].absoluteError / scale);
        if (i > 0)
            draw->AddLine(toScreen(static_cast<double>(riemannSeries_[i - 1].samples),
                                   riemannSeries_[i - 1].absoluteError / scale),
                          p, kRiemann, 1.5f);
        draw->AddCircleFilled(p, 2.5f, kRiemann);
    }
    ImGui::Dummy({width, height});
    ImGui::TextDisabled(infiniteVariance() ? "|error| / exact against N: this run (blue)"
                                           : "|error| / exact against N: this run (blue), grey s / sqrt(N)");
    if (!riemannSeries_.empty()) ImGui::TextDisabled("green: full Riemann sums on 1 .. 64 theta cells (~ 1/N)");
}

} // namespace radiant::app
