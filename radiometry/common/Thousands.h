#pragma once
// Counts as people read them, in the reasons the program gives and in the panels.
#include <cstddef>
#include <string>

namespace radiant {

/// 12345 -> "12,345".
inline std::string withThousands(std::size_t n) {
    std::string digits = std::to_string(n);
    for (auto i = static_cast<std::ptrdiff_t>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

} // namespace radiant
