#pragma once
// `radiant [SCENE]` opens the lab; `radiant solve|probe|render|bench ...` run without a window.
// Exit status 0 on success, 2 on bad arguments or bad input (one line on stderr).
#include <functional>
#include <vector>

namespace CLI {
class App;
}

namespace radiant::app {

int runCommandLine(int argc, char** argv);

/// Each subcommand lives in its own file and registers its options and its action here.
using CommandAction = std::function<int()>;
struct Subcommand {
    CLI::App* app = nullptr;
    CommandAction run;
};
Subcommand addSolveCommand(CLI::App& root);
Subcommand addProbeCommand(CLI::App& root);
Subcommand addRenderCommand(CLI::App& root);
Subcommand addBenchCommand(CLI::App& root);

} // namespace radiant::app
