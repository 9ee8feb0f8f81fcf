#pragma once
// Photometric units from the three radiometric bands, by Radiance's convention (Ward, "The RADIANCE
// Lighting Simulation and Rendering System", SIGGRAPH 1994): the bands' luminance weights
// Y = 0.265 R + 0.670 G + 0.065 B and one luminous efficacy, 179 lm/W, that of white light of
// equal energy in the three bands. It is the single constant that turns watts into lumens anywhere in
// the program: the photometric readouts (lx, cd/m^2, lm) and the glTF lights read in candela and lux,
// so a white lamp of I cd gives I / d^2 lx on a facing surface at distance d.
#include "radiometry/units/Quantity.h"

namespace radiant {

/// lm/W: luminous efficacy of the bands' white (Radiance's WHTEFFICACY).
inline constexpr double kLuminousEfficacy = 179.0;
/// The luminance weights of the R, G and B bands; they sum to 1, so white (1, 1, 1) has Y = 1.
inline constexpr double kLuminanceWeightR = 0.265;
inline constexpr double kLuminanceWeightG = 0.670;
inline constexpr double kLuminanceWeightB = 0.065;

/// Y of a band triple: the luminance-weighted sum, in the triple's own unit.
inline double luminanceWeighted(const Rgb& v) {
    return kLuminanceWeightR * v.x + kLuminanceWeightG * v.y + kLuminanceWeightB * v.z;
}

/// lx = lm/m^2: illuminance of an irradiance (also luminous exitance of a radiosity).
inline double illuminanceLux(const IrradianceRgb& e) { return kLuminousEfficacy * luminanceWeighted(e.value()); }
/// cd/m^2 = lm/(m^2 sr): luminance of a radiance.
inline double luminanceCdPerM2(const RadianceRgb& l) { return kLuminousEfficacy * luminanceWeighted(l.value()); }
/// lm: luminous flux of a radiant power.
inline double luminousFluxLumen(const PowerRgb& p) { return kLuminousEfficacy * luminanceWeighted(p.value()); }
/// cd = lm/sr: luminous intensity of a radiant intensity.
inline double luminousIntensityCandela(const IntensityRgb& i) { return kLuminousEfficacy * luminanceWeighted(i.value()); }

/// The bands of a light given in photometric units and a colour: the colour's shape at the luminous
/// amount asked for, so luminanceWeighted(result) x 179 = amount whatever the colour (a white light
/// of I cd is I / 179 W/sr in every band). The colour must have luminanceWeighted(colour) > 0.
inline Rgb bandsForLuminous(double amount, const Rgb& colour) {
    return colour * (amount / (kLuminousEfficacy * luminanceWeighted(colour)));
}

} // namespace radiant
