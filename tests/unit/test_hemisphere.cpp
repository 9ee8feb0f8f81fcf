// Hemispherical coordinates and the three ways to integrate over the hemisphere, checked against
// integral d omega = 2 pi, integral cos(theta) d omega = pi (docs/reference.md) and
// integral cos^2(theta) d omega = 2 pi / 3 (2 pi times integral_0^1 mu^2 d mu).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/hemisphere/HemisphereSampler.h"
#include "radiometry/hemisphere/HemisphericalCoordinates.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {
using radiant::test::kPi;
const auto one = [](Radians, Radians) { return 1.0; };
const auto cosine = [](Radians theta, Radians) { return std::cos(theta.value()); };
const auto cosineSquared = [](const glm::dvec3& d) { return d.z * d.z; };
} // namespace

TEST_SUITE("core") {

TEST_CASE("a direction goes to angles and back about any normal") {
    const std::vector<glm::dvec3> normals{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0.3, -0.4, 0.5}, {-1e-9, 1e-9, -1}};
    for (const glm::dvec3& n : normals) {
        const HemisphereFrame frame(n);
        const glm::dvec3 unitN = glm::normalize(n);
        CHECK(glm::dot(frame.tangent(), frame.bitangent()) == doctest::Approx(0.0).epsilon(1e-12));
        CHECK(glm::dot(frame.tangent(), unitN) == doctest::Approx(0.0).epsilon(1e-12));
        CHECK(glm::length(glm::cross(frame.tangent(), frame.bitangent()) - unitN) < 1e-12);  // right-handed
        for (double theta : {0.1, 0.7, 1.2, 1.5})
            for (double phi : {0.05, 2.0, 3.5, 6.2}) {
                const glm::dvec3 d = directionFromAngles(frame, {Radians(theta), Radians(phi)});
                CHECK(glm::length(d) == doctest::Approx(1.0).epsilon(1e-14).scale(0));
                CHECK(glm::dot(d, unitN) == doctest::Approx(std::cos(theta)).epsilon(1e-12).scale(0));
                const SphericalDirection back = anglesFromDirection(frame, 3.0 * d);
                CHECK(back.theta.value() == doctest::Approx(theta).epsilon(1e-12).scale(0));
                CHECK(back.phi.value() == doctest::Approx(phi).epsilon(1e-12).scale(0));
            }
    }
    CHECK_THROWS_AS(HemisphereFrame(glm::dvec3(0.0)), RadiantError);
}

TEST_CASE("the differential solid angle is sin(theta) d theta d phi") {
    CHECK(differentialSolidAngle(Radians(kPi / 6), Radians(0.01), Radians(0.02)).value() ==
          doctest::Approx(0.5 * 0.01 * 0.02).epsilon(1e-14).scale(0));
    CHECK(differentialSolidAngle(Radians(0.0), Radians(0.01), Radians(0.02)).value() == 0.0);
}

TEST_CASE("Riemann sums converge to 2 pi and pi with the midpoint rule's second order") {
    // The phi integral is exact (the integrands do not depend on phi); in theta the midpoint rule's
    // error is at most (pi/2) h^2 / 24 max|g''| for g(theta) = sin(theta) or sin(theta) cos(theta).
    struct Case {
        HemisphereIntegrand f;
        double exact;
        double maxSecondDerivative;
    };
    const std::vector<Case> cases{{one, 2 * kPi, 1.0}, {cosine, kPi, 2.0}};
    for (const Case& c : cases) {
        std::vector<double> errors;
        for (int n : {8, 16, 32, 64, 128}) {
            const HemisphereEstimate e = integrateRiemann(c.f, n, 4 * n);
            CHECK(e.samples == static_cast<std::size_t>(4 * n * n));
            CHECK(e.standardError == 0.0);
            errors.push_back(std::abs(e.value - c.exact));
        }
        for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
            const double order = std::log2(errors[k] / errors[k + 1]);
            CAPTURE(k);
            CHECK(order == doctest::Approx(2.0).epsilon(0.02).scale(0));
        }
        const double h = 0.5 * kPi / 128;
        CHECK(errors.back() <= 2 * kPi * (0.5 * kPi) * h * h / 24 * c.maxSecondDerivative);
    }
}

TEST_CASE("Monte Carlo is exact when the density is proportional to the integrand") {
    // Uniform samples of 1 and cosine samples of cos(theta) each give weight * f = constant.
    const HemisphereEstimate uniform = integrateMonteCarlo(one, HemisphereDensity::Uniform, 1000, 7);
    CHECK(uniform.value == doctest::Approx(2 * kPi).epsilon(1e-13).scale(0));
    CHECK(uniform.standardError < 1e-12);
    const HemisphereEstimate cosineWeighted = integrateMonteCarlo(cosine, HemisphereDensity::CosineWeighted, 1000, 7);
    CHECK(cosineWeighted.value == doctest::Approx(kPi).epsilon(1e-13).scale(0));
    CHECK(cosineWeighted.standardError < 1e-12);
}

TEST_CASE("Monte Carlo errors lie within a few standard errors, which shrink like 1/sqrt(N)") {
    // weight * f per sample: uniform on cos(theta) gives 2 pi mu with mu uniform on (0, 1], standard
    // deviation 2 pi / sqrt(12); cosine-weighted on cos^2 gives pi mu with mu = sqrt(u), variance
    // pi^2 (1/2 - 4/9) = pi^2 / 18.
    struct Case {
        HemisphereIntegrand f;
        HemisphereDensity density;
        double exact;
        double sigma;
    };
    const std::vector<Case> cases{
        {cosine, HemisphereDensity::Uniform, kPi, 2 * kPi / std::sqrt(12.0)},
        {cosineSquared, HemisphereDensity::CosineWeighted, 2 * kPi / 3, kPi / std::sqrt(18.0)},
    };
    for (const Case& c : cases) {
        std::vector<double> standardErrors;
        for (std::size_t n : {1000u, 4000u, 16000u, 64000u}) {
            for (std::uint64_t seed : {1u, 2u, 3u}) {
                const HemisphereEstimate e = integrateMonteCarlo(c.f, c.density, n, seed);
                CAPTURE(n);
                CAPTURE(seed);
                CHECK(std::abs(e.value - c.exact) < 4.0 * e.standardError);
                CHECK(e.standardError * std::sqrt(static_cast<double>(n)) == doctest::Approx(c.sigma).epsilon(0.05).scale(0));
                if (seed == 1) standardErrors.push_back(e.standardError);
            }
        }
        for (std::size_t k = 0; k + 1 < standardErrors.size(); ++k)
            CHECK(standardErrors[k + 1] / standardErrors[k] == doctest::Approx(0.5).epsilon(0.06).scale(0));
    }
}

TEST_CASE("samplers are deterministic per seed, replay on restart and stay on the hemisphere") {
    const HemisphereFrame frame(glm::dvec3(1, 2, 3));
    MonteCarloHemisphereSampler a(HemisphereDensity::CosineWeighted, 100, 42, frame);
    MonteCarloHemisphereSampler b(HemisphereDensity::CosineWeighted, 100, 42, frame);
    MonteCarloHemisphereSampler other(HemisphereDensity::CosineWeighted, 100, 43, frame);
    std::vector<glm::dvec3> first;
    bool differs = false;
    while (!a.done()) {
        const HemisphereSample s = a.next();
        const HemisphereSample t = b.next();
        differs = differs || other.next().direction != s.direction;
        CHECK(s.direction == t.direction);
        CHECK(glm::dot(s.direction, frame.normal()) > 0);
        CHECK(glm::dot(s.direction, frame.normal()) == doctest::Approx(std::cos(s.angles.theta.value())).scale(0));
        CHECK(s.weight == doctest::Approx(1.0 / a.pdf(s.angles.theta)).scale(0));
        first.push_back(s.direction);
    }
    CHECK(differs);
    CHECK_THROWS_AS(a.next(), RadiantError);
    a.restart();
    CHECK(a.next().direction == first.front());
}

TEST_CASE("integrating about a tilted normal with f(direction) gives the same answers") {
    const glm::dvec3 n = glm::normalize(glm::dvec3(-0.2, 0.9, 0.4));
    const auto projected = [n](const glm::dvec3& d) { return glm::dot(d, n); };
    RiemannHemisphereSampler riemann(64, 128, HemisphereFrame(n));
    CHECK(integrate(riemann, projected).value == doctest::Approx(kPi).epsilon(1e-3).scale(0));
    MonteCarloHemisphereSampler cosineSampler(HemisphereDensity::CosineWeighted, 500, 3, HemisphereFrame(n));
    CHECK(integrate(cosineSampler, projected).value == doctest::Approx(kPi).epsilon(1e-12).scale(0));
}

TEST_CASE("the accumulator shows a running estimate sample by sample") {
    RiemannHemisphereSampler sampler(10, 20);
    HemisphereAccumulator accumulator(sampler.isMonteCarlo());
    double previous = 0;
    while (!sampler.done()) {
        const HemisphereSample s = sampler.next();
        accumulator.add(s, 1.0);
        CHECK(accumulator.estimate().value > previous);
        previous = accumulator.estimate().value;
    }
    CHECK(previous == doctest::Approx(2 * kPi).epsilon(5e-3).scale(0));
    CHECK_THROWS_AS(RiemannHemisphereSampler(0, 4), RadiantError);
}

TEST_CASE("a frame turned about its normal keeps the normal and turns tangent and bitangent by the angle") {
    const HemisphereFrame frame(glm::dvec3(1, 2, 3));
    const HemisphereFrame quarter = frame.turned(Radians(kPi / 2));
    CHECK(glm::length(quarter.normal() - frame.normal()) < 1e-12);
    CHECK(glm::length(quarter.tangent() - frame.bitangent()) < 1e-12);
    CHECK(glm::length(quarter.bitangent() + frame.tangent()) < 1e-12);
    const HemisphereFrame eighth = frame.turned(Radians(kPi / 8));
    CHECK(glm::dot(eighth.tangent(), frame.tangent()) == doctest::Approx(std::cos(kPi / 8)).epsilon(1e-12).scale(0));
    CHECK(glm::dot(eighth.tangent(), eighth.bitangent()) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(glm::dot(glm::cross(eighth.tangent(), eighth.bitangent()), eighth.normal()) == doctest::Approx(1.0).epsilon(1e-12).scale(0));
}

} // TEST_SUITE
