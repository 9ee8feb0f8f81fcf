#pragma once
// Patch areas as people read them: the command line takes m^2 (--max-patch-area), the lab's meshing
// slider shows cm^2, and the reasons the program gives are printed by both.
#include <cstdio>
#include <string>

namespace radiant {

inline constexpr double kCm2PerM2 = 1e4;

/// 0.025 -> "250 cm^2".
inline std::string inSquareCentimetres(double m2) {
    char text[32];
    std::snprintf(text, sizeof text, "%g cm^2", m2 * kCm2PerM2);
    return text;
}

/// 0.025 -> "0.025 m^2 (250 cm^2)"; 1 -> "1 m^2".
inline std::string patchAreaText(double m2) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m^2", m2);
    return m2 < 1.0 ? text + (" (" + inSquareCentimetres(m2) + ")") : text;
}

} // namespace radiant
