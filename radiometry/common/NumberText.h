#pragma once
// Numbers in the reasons the program gives (errors and warnings).
#include <cstdio>
#include <string>

namespace radiant {

/// printf's "%g": 0.25 -> "0.25", 1e-7 -> "1e-07".
inline std::string numberText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// Three significant digits: 123456 -> "1.23e+05".
inline std::string threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

} // namespace radiant
