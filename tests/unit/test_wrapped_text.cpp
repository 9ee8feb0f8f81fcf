// Sidebar wrapping (app/ui/WrappedText.h): lines break at spaces, never inside "2,335" or "0.25".
#include <doctest/doctest.h>

#include <string>
#include <string_view>
#include <vector>

#include "app/ui/WrappedText.h"

using radiant::app::ui::breakAtSpaces;
using radiant::app::ui::withSuperscriptSquares;

namespace {

// One unit per character, as a monospaced font.
float characters(std::string_view piece) { return static_cast<float>(piece.size()); }

std::vector<std::string> linesOf(std::string_view text, float width) {
    std::vector<std::string> lines;
    for (const std::string_view line : breakAtSpaces(text, width, characters)) lines.emplace_back(line);
    return lines;
}

} // namespace

TEST_SUITE("wrapped text") {

TEST_CASE("a number with thousands separators stays on one line where ImGui would break after its comma") {
    // 20 columns: "on: 2,694 patches in 2," is where a break after the comma would fall.
    const auto lines = linesOf("on: 2,694 patches in 2,335 groups of 0.025 m^2", 20);
    CHECK(lines == std::vector<std::string>{"on: 2,694 patches in", "2,335 groups of", "0.025 m^2"});
    for (const std::string& line : lines) CHECK(line.size() <= 20);
}

TEST_CASE("a number stays with its unit: no break at a space after a number, one after a unit is fine") {
    // ImGui broke the grouping reason as "0.025" / "m^2 (250 cm^2)".
    CHECK(linesOf("finer than 0.025 m^2 (250 cm^2)", 14) ==
          std::vector<std::string>{"finer than", "0.025 m^2", "(250 cm^2)"});
}

TEST_CASE("squares in the commands' ASCII are shown as the sidebar writes them") {
    CHECK(withSuperscriptSquares("0.025 m^2 (250 cm^2), E in W/m^2") == "0.025 m\xC2\xB2 (250 cm\xC2\xB2), E in W/m\xC2\xB2");
    CHECK(withSuperscriptSquares("r^2 = 32 A") == "r\xC2\xB2 = 32 A");
    // Not an exponent of a unit: left as written.
    CHECK(withSuperscriptSquares("2^2 = 4, 10^20, x^23") == "2^2 = 4, 10^20, x^23");
}

TEST_CASE("lines fill up to the width, and a text that fits is one line") {
    CHECK(linesOf("a bb ccc", 8) == std::vector<std::string>{"a bb ccc"});
    CHECK(linesOf("a bb ccc", 7) == std::vector<std::string>{"a bb", "ccc"});
    CHECK(linesOf("a bb ccc", 4) == std::vector<std::string>{"a bb", "ccc"});
    CHECK(linesOf("a bb ccc", 3) == std::vector<std::string>{"a", "bb", "ccc"});
}

TEST_CASE("a word wider than the line goes on lines of its own, cut where it stops fitting") {
    CHECK(linesOf("see 61,935,000 patches", 10) == std::vector<std::string>{"see", "61,935,000", "patches"});
    CHECK(linesOf("in /a/b/c/scene.gltf: no", 6) == std::vector<std::string>{"in", "/a/b/c", "/scene", ".gltf:", "no"});
    // A character of two bytes is never cut in half (the cm\u00b2 of the meshing reasons).
    const auto lines = linesOf("\xC2\xB2\xC2\xB2\xC2\xB2", 3);
    CHECK(lines == std::vector<std::string>{"\xC2\xB2", "\xC2\xB2", "\xC2\xB2"});
}

TEST_CASE("newlines end lines, an empty paragraph is an empty line, runs of spaces at a break go") {
    CHECK(linesOf("one\n\ntwo three", 5) == std::vector<std::string>{"one", "", "two", "three"});
    CHECK(linesOf("left   right", 5) == std::vector<std::string>{"left", "right"});
    CHECK(linesOf("", 5) == std::vector<std::string>{""});
}

} // TEST_SUITE
