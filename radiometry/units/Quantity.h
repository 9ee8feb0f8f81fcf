#pragma once
// Radiometric quantities as strong types, so that a radiance can never be passed where an
// irradiance is expected. A quantity carries the exponents of its units (watt, metre, steradian);
// products and quotients derive the right type at compile time, as in Magnum's Math::Unit and
// pbrt's Point3/Vector3/Normal3 split.
#include <algorithm>
#include <utility>

#include <glm/vec3.hpp>

namespace radiant {

template <class Rep, int Watt, int Metre, int Steradian>
class Quantity {
public:
    using rep = Rep;
    static constexpr int watt = Watt;
    static constexpr int metre = Metre;
    static constexpr int steradian = Steradian;

    constexpr Quantity() = default;
    constexpr explicit Quantity(Rep value) : value_(value) {}

    /// The number in SI units (W, m, sr): the only way out of the type.
    [[nodiscard]] constexpr const Rep& value() const { return value_; }

    constexpr Quantity operator+(const Quantity& o) const { return Quantity(value_ + o.value_); }
    constexpr Quantity operator-(const Quantity& o) const { return Quantity(value_ - o.value_); }
    constexpr Quantity operator-() const { return Quantity(-value_); }
    constexpr Quantity& operator+=(const Quantity& o) { value_ += o.value_; return *this; }
    constexpr Quantity& operator-=(const Quantity& o) { value_ -= o.value_; return *this; }
    constexpr Quantity operator*(double s) const { return Quantity(value_ * s); }
    constexpr Quantity operator/(double s) const { return Quantity(value_ / s); }
    friend constexpr Quantity operator*(double s, const Quantity& q) { return q * s; }
    constexpr bool operator==(const Quantity&) const = default;

private:
    Rep value_{};
};

namespace detail {
template <class A, class B>
using ProductRep = decltype(std::declval<A>() * std::declval<B>());
}

template <class RA, int WA, int MA, int SA, class RB, int WB, int MB, int SB>
constexpr auto operator*(const Quantity<RA, WA, MA, SA>& a, const Quantity<RB, WB, MB, SB>& b) {
    using R = detail::ProductRep<RA, RB>;
    if constexpr (WA + WB == 0 && MA + MB == 0 && SA + SB == 0)
        return R(a.value() * b.value());
    else
        return Quantity<R, WA + WB, MA + MB, SA + SB>(a.value() * b.value());
}

template <class RA, int WA, int MA, int SA, class RB, int WB, int MB, int SB>
constexpr auto operator/(const Quantity<RA, WA, MA, SA>& a, const Quantity<RB, WB, MB, SB>& b) {
    using R = decltype(std::declval<RA>() / std::declval<RB>());
    if constexpr (WA == WB && MA == MB && SA == SB)
        return R(a.value() / b.value());
    else
        return Quantity<R, WA - WB, MA - MB, SA - SB>(a.value() / b.value());
}

// Scalar quantities.
using Length = Quantity<double, 0, 1, 0>;              ///< m
using Area = Quantity<double, 0, 2, 0>;                ///< m^2
using SolidAngle = Quantity<double, 0, 0, 1>;          ///< sr (also projected solid angle)
using Power = Quantity<double, 1, 0, 0>;               ///< W (radiant flux)
using Irradiance = Quantity<double, 1, -2, 0>;         ///< W/m^2: irradiance, radiosity, exitance
using Radiance = Quantity<double, 1, -2, -1>;          ///< W/(m^2 sr)
using Intensity = Quantity<double, 1, 0, -1>;          ///< W/sr (radiant intensity of a point source)

/// Three spectral bands (R, G, B), each solved independently.
using Rgb = glm::dvec3;
/// The largest of the three bands.
[[nodiscard]] inline double maxBand(const Rgb& v) { return std::max({v.x, v.y, v.z}); }
using PowerRgb = Quantity<Rgb, 1, 0, 0>;
using IrradianceRgb = Quantity<Rgb, 1, -2, 0>;
using RadianceRgb = Quantity<Rgb, 1, -2, -1>;
using IntensityRgb = Quantity<Rgb, 1, 0, -1>;

// Radiosity and exitance share irradiance's unit; the names say which is meant.
using Radiosity = Irradiance;
using Exitance = Irradiance;
using RadiosityRgb = IrradianceRgb;
using ExitanceRgb = IrradianceRgb;

namespace literals {
constexpr Length operator""_m(long double v) { return Length(static_cast<double>(v)); }
constexpr Area operator""_m2(long double v) { return Area(static_cast<double>(v)); }
constexpr SolidAngle operator""_sr(long double v) { return SolidAngle(static_cast<double>(v)); }
constexpr Power operator""_W(long double v) { return Power(static_cast<double>(v)); }
} // namespace literals

} // namespace radiant
