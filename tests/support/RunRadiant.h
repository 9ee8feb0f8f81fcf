#pragma once
// Runs the radiant binary the tests were built with (RADIANT_BINARY) as a user would, stdout and
// stderr apart, for what only the command line does (exit codes, warnings on stderr, JSON output).
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <doctest/doctest.h>

namespace radiant::test {

struct CommandRun {
    int status = -1;  ///< exit status; -1 when killed
    std::string out;
    std::string err;
};

/// `arguments` are passed to the shell as written (quote paths). `timeout` only ends a hang: it is
/// far above any command's time on a loaded machine.
inline CommandRun runRadiant(const std::string& arguments) {
    static int calls = 0;
    const std::string errFile = (std::filesystem::temp_directory_path() /
                                 ("radiant-test-" + std::to_string(::getpid()) + "-" + std::to_string(++calls) + ".err"))
                                    .string();
    const std::string command = "timeout 600 '" + std::string(RADIANT_BINARY) + "' " + arguments + " 2>'" + errFile + "'";
    CommandRun run;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe)) run.out += chunk.data();
    const int status = pclose(pipe);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(errFile);
    run.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::filesystem::remove(errFile);
    return run;
}

} // namespace radiant::test
