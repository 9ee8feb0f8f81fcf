#include "radiometry/hemisphere/HemisphereSampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "radiometry/common/Error.h"

namespace radiant {

namespace {
constexpr double kPi = std::numbers::pi;

[[noreturn]] void throwExhausted(std::size_t count) {
    throw RadiantError({"", "hemisphere sampler"},
                       "all " + std::to_string(count) + " samples were taken; restart() to replay them");
}
} // namespace

RiemannHemisphereSampler::RiemannHemisphereSampler(int thetaCells, int phiCells, const HemisphereFrame& frame)
    : thetaCells_(thetaCells), phiCells_(phiCells), frame_(frame) {
    if (thetaCells <= 0 || phiCells <= 0)
        throw RadiantError({"", "Riemann hemisphere sampler"}, "cell counts must be positive, got " +
                                                                   std::to_string(thetaCells) + " x " +
                                                                   std::to_string(phiCells));
}

std::size_t RiemannHemisphereSampler::sampleCount() const {
    return static_cast<std::size_t>(thetaCells_) * static_cast<std::size_t>(phiCells_);
}

HemisphereSample RiemannHemisphereSampler::next() {
    if (done()) throwExhausted(sampleCount());
    const std::size_t phiCells = static_cast<std::size_t>(phiCells_);
    const auto i = static_cast<double>(taken_ / phiCells);
    const auto j = static_cast<double>(taken_ % phiCells);
    ++taken_;
    const Radians dTheta(0.5 * kPi / thetaCells_);
    const Radians dPhi(2.0 * kPi / phiCells_);
    const SphericalDirection angles{dTheta * (i + 0.5), dPhi * (j + 0.5)};
    return {angles, directionFromAngles(frame_, angles), differentialSolidAngle(angles.theta, dTheta, dPhi).value()};
}

MonteCarloHemisphereSampler::MonteCarloHemisphereSampler(HemisphereDensity density, std::size_t samples,
                                                         std::uint64_t seed, const HemisphereFrame& frame)
    : density_(density), samples_(samples), seed_(seed), frame_(frame), generator_(seed) {}

void MonteCarloHemisphereSampler::restart() {
    generator_.seed(seed_);
    taken_ = 0;
}

double MonteCarloHemisphereSampler::uniform01() {
    // The top 53 bits as a double in [0, 1): exactly representable, identical on every platform.
    return static_cast<double>(generator_() >> 11) * 0x1.0p-53;
}

double MonteCarloHemisphereSampler::pdf(Radians theta) const {
    const double cosTheta = std::cos(theta.value());
    if (cosTheta <= 0) return 0;
    return density_ == HemisphereDensity::Uniform ? 1.0 / (2.0 * kPi) : cosTheta / kPi;
}

HemisphereSample MonteCarloHemisphereSampler::next() {
    if (done()) throwExhausted(samples_);
    ++taken_;
    const double u1 = uniform01();
    const double u2 = uniform01();
    // 1 - u lies in (0, 1], so cos(theta) > 0 and the weight 1 / pdf stays finite.
    double cosTheta = 0;
    double weight = 0;
    if (density_ == HemisphereDensity::Uniform) {
        cosTheta = 1.0 - u1;  // cos(theta) is uniform when directions are uniform in solid angle
        weight = 2.0 * kPi;
    } else {
        cosTheta = std::sqrt(1.0 - u1);  // Malley: uniform on the disk, projected up
        weight = kPi / cosTheta;
    }
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const SphericalDirection angles{Radians(std::atan2(sinTheta, cosTheta)), Radians(2.0 * kPi * u2)};
    const glm::dvec3 local(sinTheta * std::cos(angles.phi.value()), sinTheta * std::sin(angles.phi.value()),
                           cosTheta);
    return {angles, frame_.toWorld(local), weight};
}

void HemisphereAccumulator::add(const HemisphereSample& sample, double f) {
    const double x = sample.weight * f;
    ++count_;
    if (!monteCarlo_) {
        sum_ += x;
        return;
    }
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(count_);
    m2_ += delta * (x - mean_);
}

HemisphereEstimate HemisphereAccumulator::estimate() const {
    if (!monteCarlo_) return {sum_, 0.0, count_};
    const double n = static_cast<double>(count_);
    const double standardError = count_ > 1 ? std::sqrt(m2_ / (n - 1.0) / n) : 0.0;
    return {mean_, standardError, count_};
}

void HemisphereAccumulator::clear() {
    count_ = 0;
    sum_ = mean_ = m2_ = 0;
}

HemisphereEstimate integrate(HemisphereSampler& sampler, const HemisphereIntegrand& f) {
    HemisphereAccumulator accumulator(sampler.isMonteCarlo());
    while (!sampler.done()) {
        const HemisphereSample sample = sampler.next();
        accumulator.add(sample, f(sample));
    }
    return accumulator.estimate();
}

HemisphereEstimate integrateRiemann(const HemisphereIntegrand& f, int thetaCells, int phiCells) {
    RiemannHemisphereSampler sampler(thetaCells, phiCells);
    return integrate(sampler, f);
}

HemisphereEstimate integrateMonteCarlo(const HemisphereIntegrand& f, HemisphereDensity density, std::size_t samples,
                                       std::uint64_t seed) {
    MonteCarloHemisphereSampler sampler(density, samples, seed);
    return integrate(sampler, f);
}

} // namespace radiant
