#pragma once
// Plane angles with the unit in the type (as Magnum's Deg/Rad): a degree value cannot reach a
// trigonometric function without an explicit conversion.
#include <compare>
#include <numbers>

namespace radiant {

class Degrees;

class Radians {
public:
    constexpr Radians() = default;
    constexpr explicit Radians(double value) : value_(value) {}
    constexpr Radians(Degrees d);  // NOLINT: converting between angle units is always exact enough
    [[nodiscard]] constexpr double value() const { return value_; }
    constexpr auto operator<=>(const Radians&) const = default;
    constexpr Radians operator+(Radians o) const { return Radians(value_ + o.value_); }
    constexpr Radians operator-(Radians o) const { return Radians(value_ - o.value_); }
    constexpr Radians operator*(double s) const { return Radians(value_ * s); }
    constexpr Radians operator/(double s) const { return Radians(value_ / s); }

private:
    double value_ = 0;
};

class Degrees {
public:
    constexpr Degrees() = default;
    constexpr explicit Degrees(double value) : value_(value) {}
    constexpr Degrees(Radians r) : value_(r.value() * 180.0 / std::numbers::pi) {}  // NOLINT
    [[nodiscard]] constexpr double value() const { return value_; }
    constexpr auto operator<=>(const Degrees&) const = default;

private:
    double value_ = 0;
};

constexpr Radians::Radians(Degrees d) : value_(d.value() * std::numbers::pi / 180.0) {}

namespace literals {
constexpr Degrees operator""_deg(long double v) { return Degrees(static_cast<double>(v)); }
constexpr Radians operator""_rad(long double v) { return Radians(static_cast<double>(v)); }
} // namespace literals

} // namespace radiant
