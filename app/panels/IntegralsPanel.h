#pragma once
// Integrals you can watch: over the hemisphere, the integral of d omega (2 pi sr), of cos(theta)
// d omega (pi sr: why B = pi L) and of L cos(theta) d omega (the irradiance E at the probe point,
// L from the hemicube's view of the solve), estimated by a Riemann sum in theta/phi or by uniform or
// cosine-weighted Monte Carlo. Samples land on a hemisphere diagram as they are taken; the error is
// plotted against the sample count on log-log axes beside the 1/sqrt(N) line.
#include <memory>
#include <optional>
#include <vector>

#include "app/panels/HemicubeSession.h"
#include "app/panels/HemisphereIntegralRun.h"
#include "app/panels/Panel.h"

namespace radiant::app {

enum class HemisphereIntegrand { SolidAngle, ProjectedSolidAngle, Irradiance };

class IntegralsPanel final : public Panel {
public:
    /// `session` may be null: then only the two geometric integrals are offered.
    explicit IntegralsPanel(std::shared_ptr<HemicubeSession> session);

    [[nodiscard]] const char* title() const override { return "Integrals"; }
    [[nodiscard]] bool openByDefault() const override { return false; }
    void update() override;
    void draw() override;

    void select(HemisphereIntegrand integrand, const IntegralSettings& settings);
    void run(bool on) { running_ = on; }
    [[nodiscard]] bool busy() const override { return running_; }
    /// Cosine-weighted Monte Carlo of the plain solid angle: the estimator pi / cos theta has no
    /// finite variance, so no standard error is shown for it.
    [[nodiscard]] bool infiniteVariance() const {
        return integrand_ == HemisphereIntegrand::SolidAngle && settings_.method == IntegralMethod::CosineMonteCarlo;
    }
    [[nodiscard]] const HemisphereIntegralRun& current() const { return *run_; }
    HemisphereIntegralRun& current() { return *run_; }

private:
    void rebuild();
    void drawDiagram(float side) const;
    void drawErrorPlot(float width, float height) const;

    std::shared_ptr<HemicubeSession> session_;
    HemisphereIntegrand integrand_ = HemisphereIntegrand::ProjectedSolidAngle;
    IntegralSettings settings_;
    int band_ = 1;  ///< which colour band's E
    int samplesPerFrame_ = 20;
    bool running_ = false;
    std::unique_ptr<HemisphereIntegralRun> run_;
    std::vector<ErrorPoint> riemannSeries_;  ///< Riemann: one point per full grid
};

} // namespace radiant::app
