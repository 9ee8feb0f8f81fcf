#include <CLI/CLI.hpp>

#include "app/cli/CommandLine.h"
#include "radiometry/common/Error.h"

namespace radiant::app {

// PLACEHOLDER until its issue lands: refuses to run rather than print made-up numbers.
Subcommand addRenderCommand(CLI::App& root) {
    CLI::App* sub = root.add_subcommand("render", "(not available yet)");
    sub->allow_extras();
    return {sub, [] () -> int { throw RadiantError({"", "render"}, "not available in this build yet"); }};
}

} // namespace radiant::app
