// The program is relocatable (issue #19): it finds its built-in scenes beside itself, in
// ../share/radiant/assets as installed, and nowhere else. A copy of the built binary is run from
// made-up install trees; no path of the source tree is compiled in (the ctest "no_build_paths"
// reads the binary for that).
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "tests/support/Common.h"

namespace fs = std::filesystem;

namespace {

struct InstalledRun {
    int status = -1;
    std::string output;
};

/// Runs a command from `folder` (so the current directory cannot be what finds the scenes),
/// standard error with standard output.
InstalledRun runIn(const fs::path& folder, const std::string& command) {
    const std::string line = "cd '" + folder.string() + "' && " + command + " 2>&1";
    FILE* pipe = popen(line.c_str(), "r");
    REQUIRE(pipe);
    InstalledRun run;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe)) run.output += chunk.data();
    const int status = pclose(pipe);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

/// A fresh folder under the system's temporary folder, removed at the end of the test.
struct TemporaryFolder {
    fs::path path;
    TemporaryFolder() {
        path = fs::temp_directory_path() / ("radiant-relocatable-" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TemporaryFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
};

using radiant::test::contains;

} // namespace

TEST_CASE("an installed copy finds its built-in scenes in ../share/radiant/assets beside itself") {
    const TemporaryFolder prefix;
    fs::create_directories(prefix.path / "bin");
    fs::create_directories(prefix.path / "share" / "radiant" / "assets");
    fs::copy_file(RADIANT_BINARY, prefix.path / "bin" / "radiant");
    // Only the unit cube is "installed": a scene the program finds must come from this tree.
    fs::copy_file(fs::path(RADIANT_SOURCE_DIR) / "assets" / "unit-cube.gltf",
                  prefix.path / "share" / "radiant" / "assets" / "unit-cube.gltf");
    fs::create_directories(prefix.path / "elsewhere");
    const std::string program = "'" + (prefix.path / "bin" / "radiant").string() + "'";

    const InstalledRun cube = runIn(prefix.path / "elsewhere", program + " solve unit-cube --max-patch-area 0.05 --json -");
    INFO(cube.output);
    CHECK(cube.status == 0);
    CHECK(contains(cube.output, "\"scene\": \"unit-cube\""));

    // The Cornell box is in the source tree but not in this install: not found, one line, exit 2.
    const InstalledRun box = runIn(prefix.path / "elsewhere", program + " solve cornell-box");
    INFO(box.output);
    CHECK(box.status == 2);
    CHECK(contains(box.output, "cornell-box.gltf"));
}

TEST_CASE("a copy with no scenes beside it says where it looked, exit status 2") {
    const TemporaryFolder folder;
    fs::copy_file(RADIANT_BINARY, folder.path / "radiant");
    const InstalledRun run = runIn(folder.path, "'" + (folder.path / "radiant").string() + "' solve unit-cube");
    INFO(run.output);
    CHECK(run.status == 2);
    CHECK(contains(run.output, "the built-in scenes' folder was not found"));
    CHECK(contains(run.output, "share/radiant/assets"));
    CHECK(run.output.find('\n') == run.output.size() - 1);  // one line
}

TEST_CASE("radiant --version prints the project's version") {
    const InstalledRun run = runIn(fs::temp_directory_path(), std::string("'") + RADIANT_BINARY + "' --version");
    CHECK(run.status == 0);
    CHECK(run.output == std::string("radiant ") + RADIANT_VERSION + "\n");
}
