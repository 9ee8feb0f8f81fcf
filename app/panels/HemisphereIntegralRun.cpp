#include "app/panels/HemisphereIntegralRun.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace radiant::app {
namespace {

std::unique_ptr<HemisphereSampler> makeSampler(const IntegralSettings& s) {
    switch (s.method) {
    case IntegralMethod::Riemann: return std::make_unique<RiemannHemisphereSampler>(s.thetaCells, 4 * s.thetaCells);
    case IntegralMethod::UniformMonteCarlo:
        return std::make_unique<MonteCarloHemisphereSampler>(HemisphereDensity::Uniform, s.samples, s.seed);
    case IntegralMethod::CosineMonteCarlo:
        return std::make_unique<MonteCarloHemisphereSampler>(HemisphereDensity::CosineWeighted, s.samples, s.seed);
    }
    return nullptr;
}

} // namespace

HemisphereIntegralRun::HemisphereIntegralRun(std::function<double(const glm::dvec3&)> integrand, double exact,
                                             const IntegralSettings& settings)
    : integrand_(std::move(integrand)), exact_(exact), settings_(settings), sampler_(makeSampler(settings)),
      accumulator_(sampler_->isMonteCarlo()) {}

bool HemisphereIntegralRun::step(std::size_t count) {
    for (std::size_t i = 0; i < count && !sampler_->done(); ++i) {
        const HemisphereSample sample = sampler_->next();
        accumulator_.add(sample, integrand_(sample.direction));
        recent_.push_back(sample.direction);
        if (recent_.size() > kRecentSamples) recent_.pop_front();
        const std::size_t n = sampler_->taken();
        // A Riemann sum is only a quadrature once every cell is in; its partial sums are not estimates.
        const bool record = sampler_->isMonteCarlo() ? (n >= nextRecord_ || sampler_->done()) : sampler_->done();
        if (record) {
            const HemisphereEstimate e = accumulator_.estimate();
            history_.push_back({n, std::abs(e.value - exact_), e.standardError});
            while (nextRecord_ <= n) nextRecord_ = std::max(nextRecord_ + 1, static_cast<std::size_t>(std::ceil(static_cast<double>(nextRecord_) * 1.2)));
        }
    }
    return !sampler_->done();
}

void HemisphereIntegralRun::reset() {
    sampler_->restart();
    accumulator_.clear();
    history_.clear();
    recent_.clear();
    nextRecord_ = 1;
}

} // namespace radiant::app
