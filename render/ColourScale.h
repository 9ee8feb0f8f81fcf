#pragma once
// The numbers behind the pictures, GL-free so tests and the Display panel's legend use exactly what
// the shaders do: the ACES-fitted tone curve, sRGB encoding, the viridis colour map, and the
// W/m^2 range false colour maps with its legend ticks. shaders/patch.frag.glsl mirrors these.
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace radiant::render {


/// Narkowicz's fit of the ACES filmic curve (2015): x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14),
/// clamped to [0, 1]; applied per channel to linear values.
double acesFitted(double x);
/// The sRGB transfer function (IEC 61966-2-1) from linear [0, 1] to encoded [0, 1].
double linearToSrgb(double linear);

/// linearToSrgb(acesFitted(x)) from a table, for the tens of thousands of values recoloured on every
/// new solution: std::pow per band was most of the main thread's work per snapshot. Sampled on
/// u = sqrt(x / saturation) (the curve is steepest near 0) and linearly interpolated; within 1e-5 of
/// the exact curve (tested), where one 8-bit display step is 3.9e-3.
class ToneCurveTable {
public:
    ToneCurveTable();
    [[nodiscard]] float operator()(double x) const;
    /// Where acesFitted reaches 1 (0.08 x^2 - 0.56 x - 0.14 = 0): beyond it every value shows white.
    static constexpr double kSaturation = 7.2420;

private:
    static constexpr int kEntries = 4096;
    float entries_[kEntries + 1];
};

/// Viridis (van der Walt and Smith, matplotlib 2015) at t in [0, 1], clamped; linear interpolation
/// of a 9-entry table of sRGB-encoded colours. The shader holds the same table.
glm::dvec3 viridis(double t);

/// What false colour shows and its unit, for every legend (3D view, render PNGs, Display panel).
inline constexpr const char* kFalseColourQuantity = "radiosity, sum of R+G+B";
inline constexpr const char* kFalseColourUnit = "W/m^2";
/// With photometric units on: the illuminance each patch receives, E = (B - M) / rho per band (the
/// radiosity equation read backwards), as 179 lm/W x Y(E) (radiometry/units/Photometry.h).
inline constexpr const char* kIlluminanceQuantity = "illuminance";
inline constexpr const char* kIlluminanceUnit = "lx";

/// What false colour maps: [minW_m2, maxW_m2] to [0, 1] of the colour map, linearly or on log10.
/// The values are in `unit` (W/m^2 unless photometric: lx); the names keep the radiometric default.
struct ColourLegend {
    const char* quantity = kFalseColourQuantity;
    const char* unit = kFalseColourUnit;
    double minW_m2 = 0;
    double maxW_m2 = 1;
    bool logScale = false;
    /// Round values inside the range, for labels and isolines: linear, every step of 1, 2 or 5 x 10^k;
    /// log, 1, 2 and 5 in every decade.
    std::vector<double> ticksW_m2;

    /// Position of a value on the colour map, in [0, 1] (clamped).
    [[nodiscard]] double position(double valueW_m2) const;
    /// A coordinate along the colour map that is an integer exactly at each tick and continuous in
    /// between (shaders/patch.frag.glsl draws an isoline where it crosses an integer; it mirrors this).
    /// Linear: value / step. Log: 3 per decade, piecewise linear in the value within 1-2, 2-5, 5-10.
    [[nodiscard]] double isolineCoordinate(double position) const;
    /// The linear tick step (the shader's isolineScale is range / step); 0 for a log legend.
    [[nodiscard]] double linearStepW_m2() const;
};

/// A linear legend from 0 to maxW_m2, or a log legend over `decades` decades below it, with round ticks.
ColourLegend makeLegend(double maxW_m2, bool logScale, int decades);


/// A tick's label: short, exact for 1-2-5 values ("0", "0.02", "500", "2k", "1e-05").
std::string formatLegendTick(double valueW_m2);

} // namespace radiant::render
