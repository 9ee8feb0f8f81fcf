// Point sources, diffuse emitters, distant sources and the lecture's Sun example, against the
// lecture's numbers and closed forms from docs/reference.md.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "radiometry/common/Error.h"
#include "radiometry/hemisphere/HemisphereSampler.h"
#include "radiometry/solidangle/ClosedFormSolidAngles.h"
#include "radiometry/sources/DiffuseEmitter.h"
#include "radiometry/sources/DistantSource.h"
#include "radiometry/sources/PointSource.h"
#include "radiometry/sources/SunExample.h"
#include "tests/support/Common.h"

using namespace radiant;

namespace {
using radiant::test::kPi;
}

TEST_SUITE("core") {

TEST_CASE("a point source follows the inverse-square and cosine laws") {
    for (double watts : {1.0, 60.0, 1e3}) {
        const Intensity intensity = isotropicIntensity(Power(watts));
        CHECK(intensity.value() == doctest::Approx(watts / (4 * kPi)).epsilon(1e-14).scale(0));
        for (double r : {0.5, 1.0, 3.0}) {
            const double normal = pointSourceIrradiance(intensity, Length(r), Radians(0.0)).value();
            CHECK(normal == doctest::Approx(watts / (4 * kPi * r * r)).epsilon(1e-14).scale(0));  // P spread over 4 pi r^2
            CHECK(pointSourceIrradiance(intensity, Length(2 * r), Radians(0.0)).value() ==
                  doctest::Approx(normal / 4).epsilon(1e-14).scale(0));
            for (double theta : {0.3, 1.0, 1.5})
                CHECK(pointSourceIrradiance(intensity, Length(r), Radians(theta)).value() ==
                      doctest::Approx(normal * std::cos(theta)).epsilon(1e-12).scale(0));
            CHECK(pointSourceIrradiance(intensity, Length(r), Radians(2.0)).value() == 0.0);
        }
        // From positions: a source 2 m above and 1 m across a floor point, normal +z: cos = 2 / sqrt(5).
        const double expected = intensity.value() * (2 / std::sqrt(5.0)) / 5.0;
        CHECK(pointSourceIrradiance(intensity, {1, 0, 2}, {0, 0, 0}, {0, 0, 1}).value() ==
              doctest::Approx(expected).epsilon(1e-13).scale(0));
    }
    CHECK_THROWS_AS(pointSourceIrradiance(Intensity(1.0), Length(0.0), Radians(0.0)), RadiantError);
    CHECK_THROWS_AS(isotropicIntensity(Power(-1.0)), RadiantError);
}

TEST_CASE("the power a disk receives from a point source is the intensity times the cone's solid angle") {
    // Integrate E = I cos(theta) / r^2 over a disk of radius a at distance h by the midpoint rule in
    // the radius, and compare with I 2 pi (1 - h / sqrt(h^2 + a^2)).
    const Intensity intensity = isotropicIntensity(Power(100.0));
    for (double a : {0.5, 2.0})
        for (double h : {0.3, 1.0}) {
            const int rings = 4000;
            double power = 0;
            for (int k = 0; k < rings; ++k) {
                const double rho = (k + 0.5) * a / rings;
                const double r = std::hypot(rho, h);
                power += pointSourceIrradiance(intensity, Length(r), Radians(std::atan2(rho, h))).value() * 2 * kPi *
                         rho * (a / rings);
            }
            const double cone = coneSolidAngle(Radians(std::atan2(a, h))).value();
            CHECK(power == doctest::Approx(intensity.value() * cone).epsilon(1e-6).scale(0));
        }
}

TEST_CASE("a diffuse emitter: P = pi L A, B = pi L, and the hemisphere integral agrees") {
    for (double L : {1.0, 250.0})
        for (double A : {0.01, 2.0}) {
            const Power P = diffuseEmitterPower(Radiance(L), Area(A));
            CHECK(P.value() == doctest::Approx(kPi * L * A).epsilon(1e-14).scale(0));
            CHECK(diffuseEmitterRadiance(P, Area(A)).value() == doctest::Approx(L).epsilon(1e-14).scale(0));
            // P = A integral L cos(theta) d omega, by quadrature over the hemisphere.
            const double quadrature =
                A * integrateRiemann([L](Radians theta, Radians) { return L * std::cos(theta.value()); }, 1000, 4)
                        .value;
            CHECK(P.value() == doctest::Approx(quadrature).epsilon(1e-6).scale(0));
            CHECK(radiosityFromRadiance(Radiance(L)).value() == doctest::Approx(kPi * L).epsilon(1e-14).scale(0));
            CHECK(radianceFromRadiosity(Radiosity(kPi * L)).value() == doctest::Approx(L).epsilon(1e-14).scale(0));
        }
    const RadianceRgb rgb = radianceFromRadiosity(RadiosityRgb(Rgb(kPi, 2 * kPi, 0)));
    CHECK(rgb.value().y == doctest::Approx(2.0).scale(0));
}

TEST_CASE("a distant source: E = L omega, the small-cap limit of the exact disk irradiance") {
    // A uniform cap of half-angle alpha overhead gives exactly E = pi L sin^2(alpha).
    for (double alpha : {0.2, 0.02, 0.00465}) {
        const double L = 3.0;
        const double exact = kPi * L * std::sin(alpha) * std::sin(alpha);
        const double approximate = distantSourceIrradiance(Radiance(L), coneSolidAngle(Radians(alpha))).value();
        // L omega / exact = 2 / (1 + cos alpha): the relative error is about alpha^2 / 4.
        CHECK(std::abs(approximate / exact - 1) < 0.3 * alpha * alpha);
    }
    CHECK(distantSourceIrradiance(Radiance(2.0), SolidAngle(0.1), Radians(kPi / 3)).value() ==
          doctest::Approx(0.1).epsilon(1e-14).scale(0));
}

TEST_CASE("the lecture's Sun example, by its route and by geometry") {
    const SunExample sun;
    CHECK(sun.radiance().value() == doctest::Approx(2.05e7).epsilon(2e-3).scale(0));
    CHECK(sun.radiance().value() == doctest::Approx(3.91e26 / (kPi * 6.07e18)).epsilon(1e-14).scale(0));
    // The lecture's rounded solid angles.
    CHECK(sun.powerOnReceiver(sun.lectureEarthSolidAngle).value() == doctest::Approx(1373.5).epsilon(2e-3).scale(0));
    CHECK(sun.powerOnReceiver(sun.lectureMarsSolidAngle).value() == doctest::Approx(598.6).epsilon(2e-3).scale(0));
    // From geometry.
    CHECK(sun.sunRadius().value() == doctest::Approx(6.95e8).epsilon(1e-3).scale(0));
    const SolidAngle earth = sun.projectedAreaSolidAngle(sun.earthDistance());
    const SolidAngle mars = sun.projectedAreaSolidAngle(sun.marsDistance());
    CHECK(earth.value() == doctest::Approx(6.78e-5).epsilon(2e-3).scale(0));
    CHECK(sun.irradiance(earth).value() == doctest::Approx(1390).epsilon(2e-3).scale(0));
    CHECK(earth.value() == doctest::Approx(sun.lectureEarthSolidAngle.value()).epsilon(0.015).scale(0));
    CHECK(mars.value() == doctest::Approx(sun.lectureMarsSolidAngle.value()).epsilon(0.015).scale(0));
    CHECK(sun.irradiance(earth).value() == doctest::Approx(1373.5).epsilon(0.015).scale(0));
    CHECK(mars.value() == doctest::Approx(earth.value() / (1.524 * 1.524)).epsilon(1e-12).scale(0));
    // pi R^2 / d^2 and the exact cap differ by ~(R/d)^2 / 4, about 5e-6 at Earth.
    CHECK(sun.exactSolidAngle(sun.earthDistance()).value() == doctest::Approx(earth.value()).epsilon(1e-5).scale(0));
    CHECK_THROWS_AS((void)sun.exactSolidAngle(Length(1e8)), RadiantError);
}

} // TEST_SUITE
