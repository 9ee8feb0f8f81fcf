#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/bench/BenchTable.h"
#include "app/cli/CommandLine.h"

namespace radiant::app {

Subcommand addBenchCommand(CLI::App& root) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* sub = root.add_subcommand("bench", "Measure loading, form factors and solvers; print tables");
    sub->add_flag("--quick", options->quick, "Fewer sizes and repeats (a smoke run, not figures to quote)");
    return {sub, [options] {
                std::printf("# radiant bench%s\n", options->quick ? " --quick" : "");
                std::printf("Medians over repeats in one run; the machine may be shared and noisy.\n");
                benchScenes(*options).print();
                benchFormFactors(*options).print();
                benchSolvers(*options).print();
                benchHemicube(*options).print();
                benchFrames(*options).print();
                return 0;
            }};
}

} // namespace radiant::app
