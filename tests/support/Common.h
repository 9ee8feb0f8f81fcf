#pragma once
// Helpers that several test files used word for word. One definition here, not one per file: a unity
// build compiles a batch of test files as one translation unit, whose anonymous namespaces are one.
#include <numbers>
#include <string>
#include <vector>

namespace radiant::test {

inline constexpr double kPi = std::numbers::pi;

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
    for (const std::string& line : lines)
        if (contains(line, part)) return true;
    return false;
}

} // namespace radiant::test
