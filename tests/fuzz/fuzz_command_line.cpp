// libFuzzer target: the input split at NUL bytes into argv (after the program name) and handed to
// radiant::app::parseCommandLine, which parses and never runs a command. Help and one-line errors
// are printed (run with -close_fd_mask=3 to hide them); a crash or an escaping exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli/CommandLine.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> words{"radiant"};
    std::string word;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word.push_back(static_cast<char>(data[i]));
        }
    }
    if (!word.empty()) words.push_back(word);
    if (words.size() > 64) return 0;  // argv longer than any shell line a student types
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    argv.push_back(nullptr);
    (void)radiant::app::parseCommandLine(static_cast<int>(words.size()), argv.data());
    return 0;
}
