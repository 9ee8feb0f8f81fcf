// The lab's shortcut table is the one list of keys: every key maps to one action, and the README's
// key table says exactly what the table does, row for row.
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include "app/ui/Shortcuts.h"

using namespace radiant::app;

TEST_SUITE("lab") {

TEST_CASE("every shortcut key triggers its own action and no key two") {
    std::set<std::pair<int, bool>> keys;
    for (const Shortcut& shortcut : labShortcuts()) {
        CAPTURE(shortcut.keys);
        CHECK(keys.insert({shortcut.key, shortcut.control}).second);
        if (shortcut.alternateKey != 0) CHECK(keys.insert({shortcut.alternateKey, shortcut.control}).second);
        REQUIRE(shortcutForKey(shortcut.key, shortcut.control));
        CHECK(shortcutForKey(shortcut.key, shortcut.control)->action == shortcut.action);
    }
    CHECK_FALSE(shortcutForKey(0));
    // Ctrl+S saves the session; S alone is the dome.
    REQUIRE(shortcutForKey('S', true));
    REQUIRE(shortcutForKey('S', false));
    CHECK(shortcutForKey('S', true)->action == LabAction::SaveSession);
    CHECK(shortcutForKey('S', false)->action == LabAction::Dome);
}

TEST_CASE("the README's key table is the shortcut table") {
    std::ifstream readme(std::string(RADIANT_SOURCE_DIR) + "/README.md");
    REQUIRE(readme);
    std::vector<std::string> rows;
    std::string line;
    bool inTable = false;
    while (std::getline(readme, line)) {
        if (line == "| key | does |") {
            inTable = true;
            std::getline(readme, line);  // the |---|---| rule
            continue;
        }
        if (inTable && line.rfind("| ", 0) != 0) break;
        if (inTable) rows.push_back(line);
    }
    std::vector<std::string> expected;
    for (const Shortcut& shortcut : labShortcuts())
        expected.push_back(std::string("| ") + shortcut.keys + " | " + shortcut.does + " |");
    CHECK(rows == expected);
}

} // TEST_SUITE
