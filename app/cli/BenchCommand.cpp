#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "app/bench/BenchTable.h"
#include "app/cli/CommandLine.h"

namespace radiant::app {

Subcommand addBenchCommand(CLI::App& root) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* sub = root.add_subcommand("bench", "Measure loading, form factors and solvers; print tables");
    sub->add_flag("--quick", options->quick, "Fewer sizes and repeats (a smoke run, not figures to quote)");
    auto only = std::make_shared<std::string>();
    sub->add_option("--only", *only, "Run one part: scenes, form-factors, solvers (with the hierarchical tables), peers (the hierarchical solver against RenderPark and SPLASH-2 alone), hierarchical-accuracy (at points, by link tolerance), hemicube, frames or accuracy (each method against the path-traced reference, on the Cornell box and on a variant with its blocks square to the walls)")
        ->check(CLI::IsMember({"scenes", "form-factors", "solvers", "peers", "hierarchical-accuracy", "hemicube", "frames", "accuracy"}));
    return {sub, [options, only] {
                const auto wanted = [&](const char* table) { return only->empty() || *only == table; };
                std::printf("# radiant bench%s\n", options->quick ? " --quick" : "");
                std::printf("Medians over repeats in one run; the machine may be shared and noisy.\n");
                if (wanted("scenes")) benchScenes(*options).print();
                if (wanted("form-factors")) benchFormFactors(*options).print();
                if (wanted("solvers")) benchSolvers(*options).print();
                if (wanted("solvers")) benchHierarchical(*options).print();
                if (wanted("solvers") || wanted("peers")) benchHierarchicalPeers(*options).print();
                if (wanted("solvers") || wanted("hierarchical-accuracy")) benchHierarchicalAccuracy(*options).print();
                if (wanted("accuracy")) benchAccuracy(*options).print();
                if (wanted("accuracy")) benchAccuracySquareBlocks(*options).print();
                if (wanted("hemicube")) benchHemicube(*options).print();
                if (wanted("frames")) benchFrames(*options).print();
                return 0;
            }};
}

} // namespace radiant::app
