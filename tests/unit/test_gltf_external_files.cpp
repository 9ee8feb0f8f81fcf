// Files that are not files (#17): a glTF whose buffer or image URI names a directory (once
// std::bad_alloc), a FIFO (once a hang), /dev/zero, or a file shorter than its byteLength is refused
// with one line naming the file, the element and the URI, before anything is read; the command line
// exits 2. The files are in tests/data/regression-gltf (written by tests/data/make_blender_scenes.py).
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"
#include "tests/support/Common.h"

using namespace radiant;
namespace fs = std::filesystem;

namespace {

std::string regressionFile(const std::string& name) { return std::string(RADIANT_TEST_DATA_DIR) + "/regression-gltf/" + name; }

using radiant::test::contains;

struct Refusal {
    std::string message;
    double seconds = 0;
};

Refusal loadRefusal(const std::string& path) {
    const auto start = std::chrono::steady_clock::now();
    Refusal refusal;
    try {
        (void)loadScene(path);
    } catch (const RadiantError& e) {
        refusal.message = e.what();
    }
    refusal.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return refusal;
}

struct CommandResult {
    int status = -1;
    std::string output;  ///< stdout and stderr together
};

/// `radiant solve PATH`'s exit status and everything it printed; `timeout` turns a hang into 124.
CommandResult solveCommand(const std::string& path) {
    const std::string command = "timeout 20 '" + std::string(RADIANT_BINARY) + "' solve '" + path + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string output;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe)) output += chunk.data();
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

/// A scratch folder removed on scope exit.
struct ScratchFolder {
    fs::path path = fs::temp_directory_path() / ("radiant-external-" + std::to_string(::getpid()));
    ScratchFolder() { fs::create_directories(path); }
    ~ScratchFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

} // namespace

TEST_SUITE("reliability") {

TEST_CASE("an external buffer or image that is not a regular file of the stated size is refused in one line") {
    struct Case {
        const char* file;
        const char* element;
        const char* problem;
    };
    const Case cases[] = {
        {"external_directory.gltf", "buffer 0 '.'", "is a directory, not a file"},
        {"external_dev_zero.gltf", "dev/zero'", "is a device, not a file"},
        {"external_short.gltf", "buffer 0 'external_short.bin'", "is 10 bytes, shorter than its byteLength 72 bytes"},
        {"external_image_directory.gltf", "image 0 '.'", "is a directory, not a file"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.file);
        const Refusal refusal = loadRefusal(regressionFile(c.file));
        INFO(refusal.message);
        CHECK(contains(refusal.message, c.file));
        CHECK(contains(refusal.message, c.element));
        CHECK(contains(refusal.message, c.problem));
        CHECK(!contains(refusal.message, "\n"));
        CHECK(refusal.seconds < 1.0);
        const CommandResult run = solveCommand(regressionFile(c.file));
        INFO(run.output);
        CHECK(run.status == 2);
        CHECK(std::count(run.output.begin(), run.output.end(), '\n') == 1);
        CHECK(contains(run.output, c.problem));
    }
}

TEST_CASE("a FIFO named by a buffer, or given as the scene, is refused without opening it for reading") {
    ScratchFolder scratch;
    fs::copy_file(regressionFile("external_fifo.gltf"), scratch.path / "external_fifo.gltf");
    REQUIRE(::mkfifo((scratch.path / "fifo.bin").c_str(), 0600) == 0);
    REQUIRE(::mkfifo((scratch.path / "scene.gltf").c_str(), 0600) == 0);
    for (const char* name : {"external_fifo.gltf", "scene.gltf"}) {
        CAPTURE(name);
        const auto start = std::chrono::steady_clock::now();
        const CommandResult run = solveCommand((scratch.path / name).string());
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        INFO(run.output);
        CHECK(run.status == 2);  // 124 would be the timeout ending a hang
        CHECK(std::count(run.output.begin(), run.output.end(), '\n') == 1);
        CHECK(contains(run.output, "is a FIFO (named pipe), not a file"));
        CHECK(seconds < 1.0);
    }
    // The scene itself a directory: refused, not std::bad_alloc.
    const CommandResult directory = solveCommand(scratch.path.string());
    INFO(directory.output);
    CHECK(directory.status == 2);
    CHECK(contains(directory.output, "is a directory, not a file"));
}

TEST_CASE("relative URIs resolve against the glTF's folder, never the current directory") {
    // A copy of a scene with an external buffer, away from its .bin; the .bin in the current
    // directory instead must not be used.
    ScratchFolder scratch;
    fs::create_directories(scratch.path / "scene");
    fs::create_directories(scratch.path / "cwd");
    const fs::path data = fs::path(RADIANT_TEST_DATA_DIR) / "gltf";
    fs::copy_file(data / "square_external.gltf", scratch.path / "scene" / "square_external.gltf");
    fs::copy_file(data / "square_external.bin", scratch.path / "cwd" / "square_external.bin");
    const fs::path here = fs::current_path();
    fs::current_path(scratch.path / "cwd");
    std::string message;
    try {
        (void)loadGltf((scratch.path / "scene" / "square_external.gltf").string());
    } catch (const RadiantError& e) {
        message = e.what();
    }
    fs::current_path(here);
    INFO(message);
    CHECK(contains(message, "buffer 0 'square_external.bin': not found in " + (scratch.path / "scene").string()));
    // Beside the glTF it loads, whatever the current directory.
    fs::copy_file(data / "square_external.bin", scratch.path / "scene" / "square_external.bin");
    CHECK(loadGltf((scratch.path / "scene" / "square_external.gltf").string()).scene.totalArea() == doctest::Approx(1.0).scale(0));
}

TEST_CASE("a file over the loader's byte budget is refused before it is read") {
    SceneLoadOptions options;
    options.fileByteBudget = 40;  // the square's buffer is 72 bytes
    try {
        (void)loadGltf(std::string(RADIANT_TEST_DATA_DIR) + "/gltf/square_external.gltf", options);
        FAIL("loaded over budget");
    } catch (const BudgetError& e) {
        INFO(e.what());
        // The glTF text itself is over 40 bytes: that is what is refused first.
        CHECK(contains(e.what(), "budget is 40 bytes"));
    }
}

} // TEST_SUITE
