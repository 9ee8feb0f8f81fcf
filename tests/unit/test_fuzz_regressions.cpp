// Inputs that once crashed (found by the fuzzers in tests/fuzz) and the from-memory loader the
// glTF fuzzer drives. Every file in tests/data/regression-gltf must end in a clean RadiantError,
// from memory and from disk; every argv in tests/data/regression-cli must parse without crashing.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app/cli/CommandLine.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/GltfLoader.h"
#include "tests/support/Common.h"

using namespace radiant;
namespace fs = std::filesystem;

namespace {

std::vector<unsigned char> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<fs::path> filesIn(const std::string& folder) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(RADIANT_TEST_DATA_DIR) / folder;
    if (fs::is_directory(dir))
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

using radiant::test::contains;

std::string memoryLoadError(const std::vector<unsigned char>& bytes) {
    try {
        (void)loadGltfFromMemory(bytes, "memory");
    } catch (const RadiantError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_SUITE("reliability") {

TEST_CASE("a glTF file loads the same from memory as from disk") {
    for (const char* name : {"cornell-box.gltf", "unit-cube.gltf"}) {
        const fs::path path = fs::path(RADIANT_SOURCE_DIR) / "assets" / name;
        const LoadedScene fromDisk = loadGltf(path.string());
        const LoadedScene fromMemory = loadGltfFromMemory(readBytes(path), name);
        CAPTURE(name);
        CHECK(fromMemory.scene.name == name);
        REQUIRE(fromMemory.scene.surfaces.size() == fromDisk.scene.surfaces.size());
        REQUIRE(fromMemory.scene.materials.size() == fromDisk.scene.materials.size());
        CHECK(fromMemory.scene.totalArea() == fromDisk.scene.totalArea());
        for (std::size_t s = 0; s < fromDisk.scene.surfaces.size(); ++s) {
            CHECK(fromMemory.scene.surfaces[s].name == fromDisk.scene.surfaces[s].name);
            CHECK(fromMemory.scene.surfaces[s].faces.size() == fromDisk.scene.surfaces[s].faces.size());
        }
    }
    // .glb is recognised by its magic, not a file extension.
    const fs::path glb = fs::path(RADIANT_TEST_DATA_DIR) / "gltf" / "square.glb";
    const LoadedScene square = loadGltfFromMemory(readBytes(glb), "square");
    CHECK(square.scene.surfaces.size() == 1);
    CHECK(square.scene.totalArea() == doctest::Approx(loadGltf(glb.string()).scene.totalArea()).scale(0));
}

TEST_CASE("from memory, external files are refused and bad bytes end in RadiantError") {
    const fs::path gltf = fs::path(RADIANT_TEST_DATA_DIR) / "gltf";
    const std::string external = memoryLoadError(readBytes(gltf / "square_external.gltf"));
    INFO(external);
    CHECK(contains(external, "memory"));
    CHECK(!external.empty());
    CHECK(contains(memoryLoadError({}), "empty"));
    for (const char* bad : {"truncated.glb", "truncated.gltf", "malformed.gltf", "index_out_of_range.gltf",
                            "accessor_overrun.gltf", "nan_position.gltf", "negative_emission.gltf"}) {
        CAPTURE(bad);
        CHECK(!memoryLoadError(readBytes(gltf / bad)).empty());
    }
}

TEST_CASE("every glTF the fuzzer crashed on is refused cleanly, from memory and from disk") {
    const auto files = filesIn("regression-gltf");
    MESSAGE(files.size() << " regression file(s)");
    for (const fs::path& file : files) {
        CAPTURE(file.filename().string());
        CHECK_THROWS_AS((void)loadGltfFromMemory(readBytes(file), file.filename().string()), RadiantError);
        CHECK_THROWS_AS((void)loadGltf(file.string()), RadiantError);
    }
}

TEST_CASE("the command-line parser survives every argv the fuzzer crashed on, and runs nothing") {
    // One argument per NUL-separated field, as the fuzz target builds argv.
    auto files = filesIn("regression-cli");
    for (const fs::path& file : files) {
        const std::vector<unsigned char> bytes = readBytes(file);
        std::vector<std::string> words{"radiant"};
        std::string word;
        for (unsigned char c : bytes) {
            if (c == 0) {
                words.push_back(word);
                word.clear();
            } else {
                word.push_back(static_cast<char>(c));
            }
        }
        if (!word.empty()) words.push_back(word);
        std::vector<const char*> argv;
        for (const std::string& w : words) argv.push_back(w.c_str());
        CAPTURE(file.filename().string());
        CHECK_NOTHROW((void)app::parseCommandLine(static_cast<int>(argv.size()), argv.data()));
    }
    // Parsing alone: a valid solve line yields an action and runs nothing; a bad one is status 2.
    const char* solve[] = {"radiant", "solve", "cornell-box", "--method", "jacobi"};
    const app::ParsedCommandLine parsed = app::parseCommandLine(5, solve);
    CHECK(static_cast<bool>(parsed.action));
    const char* bad[] = {"radiant", "solve", "--no-such-option"};
    const app::ParsedCommandLine refused = app::parseCommandLine(3, bad);
    CHECK(!refused.action);
    CHECK(refused.exitStatus == 2);
}

} // TEST_SUITE
