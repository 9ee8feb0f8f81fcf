#pragma once
// Numerical integration over the hemisphere, built so that a user interface can watch it happen:
// a sampler yields one direction at a time with its weight, an accumulator keeps the running
// estimate, and integrate() does both in one call.
//
//   Riemann (midpoint rule): N_theta x N_phi cells, sample at each cell's centre, weight = the cell's
//     solid angle sin(theta) d theta d phi; the estimate is the weighted sum. Error O(h^2).
//   Monte Carlo: independent directions drawn with density pdf(omega); weight = 1 / pdf; the estimate
//     is the mean of weight * f, its standard error s / sqrt(N). Uniform: pdf = 1 / (2 pi).
//     Cosine-weighted (Malley's method, Pharr, Jakob & Humphreys, PBRT 3rd ed., 13.6.3):
//     pdf = cos(theta) / pi, exact for f = cos(theta) and the right choice for irradiance.
#include <concepts>
#include <cstdint>
#include <functional>
#include <random>
#include <utility>

#include <glm/vec3.hpp>

#include "radiometry/hemisphere/HemisphericalCoordinates.h"

namespace radiant {

struct HemisphereSample {
    SphericalDirection angles;
    glm::dvec3 direction{0, 0, 1};  ///< unit, world coordinates (the sampler's frame applied)
    /// sr. Riemann: the cell's solid angle. Monte Carlo: 1 / pdf(direction).
    double weight = 0;
};

struct HemisphereEstimate {
    double value = 0;
    /// Monte Carlo: the sample standard deviation of weight * f over sqrt(N). Riemann: 0 (its error
    /// is deterministic discretisation error, not noise).
    double standardError = 0;
    std::size_t samples = 0;
};

/// A function over the hemisphere, given either as f(theta, phi) or as f(world direction).
class HemisphereIntegrand {
public:
    template <class F>
        requires std::invocable<const F&, Radians, Radians>
    HemisphereIntegrand(F f)  // NOLINT: implicit, so integrate() takes a lambda directly
        : f_([f = std::move(f)](const HemisphereSample& s) {
              return static_cast<double>(f(s.angles.theta, s.angles.phi));
          }) {}
    template <class F>
        requires(std::invocable<const F&, const glm::dvec3&> && !std::invocable<const F&, Radians, Radians>)
    HemisphereIntegrand(F f)  // NOLINT
        : f_([f = std::move(f)](const HemisphereSample& s) { return static_cast<double>(f(s.direction)); }) {}

    double operator()(const HemisphereSample& sample) const { return f_(sample); }

private:
    std::function<double(const HemisphereSample&)> f_;
};

/// Yields a fixed number of samples, one per next(). Deterministic: restart() replays them.
class HemisphereSampler {
public:
    virtual ~HemisphereSampler() = default;
    HemisphereSampler() = default;
    HemisphereSampler(const HemisphereSampler&) = default;
    HemisphereSampler& operator=(const HemisphereSampler&) = default;

    [[nodiscard]] virtual bool isMonteCarlo() const = 0;
    [[nodiscard]] virtual std::size_t sampleCount() const = 0;
    [[nodiscard]] virtual std::size_t taken() const = 0;
    [[nodiscard]] bool done() const { return taken() >= sampleCount(); }
    /// The next sample; throws RadiantError when all sampleCount() have been taken.
    virtual HemisphereSample next() = 0;
    virtual void restart() = 0;
};

/// Midpoint rule on a thetaCells x phiCells grid over theta in [0, pi/2], phi in [0, 2 pi).
class RiemannHemisphereSampler final : public HemisphereSampler {
public:
    /// Throws RadiantError unless both counts are positive.
    RiemannHemisphereSampler(int thetaCells, int phiCells, const HemisphereFrame& frame = {});
    [[nodiscard]] bool isMonteCarlo() const override { return false; }
    [[nodiscard]] std::size_t sampleCount() const override;
    [[nodiscard]] std::size_t taken() const override { return taken_; }
    HemisphereSample next() override;
    void restart() override { taken_ = 0; }

private:
    int thetaCells_, phiCells_;
    HemisphereFrame frame_;
    std::size_t taken_ = 0;
};

enum class HemisphereDensity {
    Uniform,        ///< pdf = 1 / (2 pi)
    CosineWeighted  ///< pdf = cos(theta) / pi
};

/// Independent random directions from std::mt19937_64 seeded with `seed`: the same seed gives the
/// same samples on every platform (the doubles are built from the generator's bits, not through
/// std::uniform_real_distribution, whose algorithm the standard leaves open).
class MonteCarloHemisphereSampler final : public HemisphereSampler {
public:
    MonteCarloHemisphereSampler(HemisphereDensity density, std::size_t samples, std::uint64_t seed,
                                const HemisphereFrame& frame = {});
    [[nodiscard]] bool isMonteCarlo() const override { return true; }
    [[nodiscard]] std::size_t sampleCount() const override { return samples_; }
    [[nodiscard]] std::size_t taken() const override { return taken_; }
    HemisphereSample next() override;
    void restart() override;
    [[nodiscard]] HemisphereDensity density() const { return density_; }
    /// The density (1/sr) at a local direction's polar angle.
    [[nodiscard]] double pdf(Radians theta) const;

private:
    double uniform01();

    HemisphereDensity density_;
    std::size_t samples_;
    std::uint64_t seed_;
    HemisphereFrame frame_;
    std::mt19937_64 generator_;
    std::size_t taken_ = 0;
};

/// The running estimate: a weighted sum for Riemann, a mean with Welford's variance for Monte Carlo.
class HemisphereAccumulator {
public:
    explicit HemisphereAccumulator(bool monteCarlo) : monteCarlo_(monteCarlo) {}
    void add(const HemisphereSample& sample, double f);
    [[nodiscard]] HemisphereEstimate estimate() const;
    void clear();

private:
    bool monteCarlo_;
    std::size_t count_ = 0;
    double sum_ = 0;   ///< Riemann: sum of weight * f
    double mean_ = 0;  ///< Monte Carlo: running mean of weight * f
    double m2_ = 0;    ///< Monte Carlo: sum of squared deviations from the mean
};

/// Takes every remaining sample of `sampler`, evaluates f, returns the estimate.
HemisphereEstimate integrate(HemisphereSampler& sampler, const HemisphereIntegrand& f);

// One-call forms over the hemisphere about +z.
HemisphereEstimate integrateRiemann(const HemisphereIntegrand& f, int thetaCells, int phiCells);
HemisphereEstimate integrateMonteCarlo(const HemisphereIntegrand& f, HemisphereDensity density, std::size_t samples,
                                       std::uint64_t seed);

} // namespace radiant
