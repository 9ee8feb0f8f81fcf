#pragma once
// One hemisphere integral being estimated a few samples at a time, so a class can watch it: the
// sampler (Riemann midpoint cells, uniform or cosine-weighted Monte Carlo; HemisphereSampler.h),
// the running estimate against the exact value, the error after each sample count (for a log-log
// plot against 1/sqrt(N)) and the recent sample directions (for the hemisphere diagram).
// UI-free, so the tests drive it.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/hemisphere/HemisphereSampler.h"

namespace radiant::app {

enum class IntegralMethod { Riemann, UniformMonteCarlo, CosineMonteCarlo };

struct IntegralSettings {
    IntegralMethod method = IntegralMethod::UniformMonteCarlo;
    int thetaCells = 16;        ///< Riemann: the grid is thetaCells x (4 thetaCells)
    std::size_t samples = 20000;///< Monte Carlo: samples in a full run
    std::uint64_t seed = 1;
};

struct ErrorPoint {
    std::size_t samples = 0;
    double absoluteError = 0;
    double standardError = 0;  ///< Monte Carlo's own error estimate s / sqrt(N); 0 for Riemann
};

class HemisphereIntegralRun {
public:
    /// f over local directions (z = normal); `exact` is the value the estimate should reach.
    HemisphereIntegralRun(std::function<double(const glm::dvec3&)> integrand, double exact,
                          const IntegralSettings& settings);

    /// Takes up to `count` more samples; false when the sampler is exhausted.
    bool step(std::size_t count);
    void reset();

    [[nodiscard]] HemisphereEstimate estimate() const { return accumulator_.estimate(); }
    [[nodiscard]] double exact() const { return exact_; }
    [[nodiscard]] bool done() const { return sampler_->done(); }
    [[nodiscard]] std::size_t taken() const { return sampler_->taken(); }
    [[nodiscard]] std::size_t total() const { return sampler_->sampleCount(); }
    [[nodiscard]] const IntegralSettings& settings() const { return settings_; }
    /// Recorded at geometrically spaced sample counts (about 12 per decade) and at the last sample.
    [[nodiscard]] const std::vector<ErrorPoint>& errorHistory() const { return history_; }
    /// The most recent sample directions (local), newest last, at most kRecentSamples.
    [[nodiscard]] const std::deque<glm::dvec3>& recentDirections() const { return recent_; }
    static constexpr std::size_t kRecentSamples = 4000;

private:
    std::function<double(const glm::dvec3&)> integrand_;
    double exact_;
    IntegralSettings settings_;
    std::unique_ptr<HemisphereSampler> sampler_;
    HemisphereAccumulator accumulator_;
    std::vector<ErrorPoint> history_;
    std::deque<glm::dvec3> recent_;
    std::size_t nextRecord_ = 1;
};

} // namespace radiant::app
