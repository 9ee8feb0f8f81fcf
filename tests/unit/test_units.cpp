#include <doctest/doctest.h>

#include <numbers>
#include <type_traits>

#include "radiometry/units/Angle.h"
#include "radiometry/units/Quantity.h"

using namespace radiant;

TEST_CASE("quantities derive their units through products and quotients") {
    const Radiance L(2.0);
    const SolidAngle omega(0.5);
    const auto E = L * omega;
    static_assert(std::is_same_v<std::remove_const_t<decltype(E)>, Irradiance>);
    CHECK(E.value() == doctest::Approx(1.0).scale(0));
    const auto P = E * Area(3.0);
    static_assert(std::is_same_v<std::remove_const_t<decltype(P)>, Power>);
    CHECK(P.value() == doctest::Approx(3.0).scale(0));
    const double ratio = Power(6.0) / Power(3.0);
    CHECK(ratio == doctest::Approx(2.0).scale(0));
    static_assert(std::is_same_v<decltype(Power(1.0) / Area(1.0)), Irradiance>);
}

TEST_CASE("degrees and radians convert explicitly") {
    const Radians r = Degrees(180.0);
    CHECK(r.value() == doctest::Approx(std::numbers::pi).scale(0));
    const Degrees d = Radians(std::numbers::pi / 2);
    CHECK(d.value() == doctest::Approx(90.0).scale(0));
}
