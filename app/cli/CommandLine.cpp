#include "app/cli/CommandLine.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/LabApp.h"
#include "generated/Version.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/GroupedSolver.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/Solver.h"

namespace radiant::app {

void writeText(const std::string& path, const std::string& text, const char* option) {
    if (path == "-") {
        std::cout << text << std::flush;
        return;
    }
    std::ofstream out(path);
    if (!out) throw RadiantError({path, option}, "cannot open for writing");
    out << text;
    if (!out) throw RadiantError({path, option}, "write failed");
}

Scene loadSceneArgument(const std::string& nameOrPath) {
    Scene scene = loadScene(nameOrPath).scene;
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
    return scene;
}

void addGroupingFlags(CLI::App& sub, GroupingFlags& flags, const std::string& what) {
    CLI::Option* on = sub.add_flag("--group-patches", flags.on,
                                   "Group adjacent patches of every smooth surface into unknowns of about --max-patch-area "
                                   "(by default only surfaces tessellated finer than it, where that at least halves their "
                                   "patches); jacobi, gauss-seidel and progressive solve groups, hierarchical and "
                                   "importance solve the patches" + what);
    CLI::Option* off = sub.add_flag("--no-group-patches", flags.off, "Solve every patch as its own unknown");
    on->excludes(off);
}

CommandSystem meshForCommand(const std::string& namedMethod, const Scene& scene, double maxPatchArea, GroupingMode grouping) {
    MeshingOptions meshing;
    meshing.maxPatchArea = maxPatchArea;
    CommandSystem system;
    system.rays = std::make_shared<const RayCaster>(scene);
    system.mesh = meshScene(scene, meshing, nullptr, system.rays.get());
    std::optional<SolverMethod> named;
    if (!namedMethod.empty()) named = parseMethod(namedMethod);
    SystemChoice choice = chooseSystem(system.mesh, maxPatchArea, grouping, named);
    system.groups = std::move(choice.groups);
    system.groupingReason = std::move(choice.groupingReason);
    system.choice = std::move(choice.method);
    // Said when it changes what is solved or what was asked; the ungrouped default is said in the
    // JSON only, so a scene of large quads prints what it always printed.
    if (system.groups || choice.methodTakesNoGroups || grouping == GroupingMode::On)
        std::fprintf(stderr, "radiant: grouping: %s\n", system.groupingReason.c_str());
    if (!named)
        std::fprintf(stderr, "radiant: method: %s (%s)\n", std::string(methodName(system.choice.method)).c_str(),
                     system.choice.reason.c_str());
    return system;
}

std::unique_ptr<Solver> makeCommandSolver(const Scene& scene, const CommandSystem& system, const SolverOptions& options,
                                          Progress* progress) {
    const SolverMethod method = system.choice.method;
    SolverOptions shared = options;
    if (!shared.rays) shared.rays = system.rays;
    try {
        return system.groups ? makeGroupedSolver(method, scene, system.mesh, system.groups, shared, progress)
                             : makeSolver(method, scene, system.mesh, shared, progress);
    } catch (const BudgetError& e) {
        if (!e.where().file.empty()) throw;
        throw BudgetError({scene.name, e.where().element}, e.detail());  // which file is too big
    }
}

std::string methodOptionHelp() {
    return methodNameList() + "; default: " + std::string(methodName(kSolveDefaults.method)) + " up to " +
           std::to_string(kProgressiveMaxPatches) + " unknowns (patches, or their groups), hierarchical beyond";
}

ParsedCommandLine parseCommandLine(int argc, const char* const* argv) {
    CLI::App root{"Radiant: an interactive lab for radiometry and radiosity", "radiant"};
    root.require_subcommand(0, 1);
    root.set_version_flag("--version", std::string("radiant ") + kRadiantVersion);
    auto scene = std::make_shared<std::string>("cornell-box");
    root.add_option("scene", *scene, "glTF file or built-in scene name to open in the lab")->capture_default_str();
    auto lesson = std::make_shared<std::string>();
    root.add_option("--lesson", *lesson, "Open the lab on this lesson file (docs/lessons.md)");

    const Subcommand commands[] = {addSolveCommand(root), addProbeCommand(root), addReferenceCommand(root),
                                   addRenderCommand(root), addBenchCommand(root), addLessonCommand(root)};
    try {
        root.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return {{}, root.exit(e)};
    } catch (const CLI::CallForAllHelp& e) {
        return {{}, root.exit(e)};
    } catch (const CLI::CallForVersion& e) {
        return {{}, root.exit(e)};
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "radiant: %s (see radiant --help)\n", e.what());
        return {{}, 2};
    }
    for (const Subcommand& command : commands)
        if (command.app->parsed()) return {command.run, 0};
    return {[scene, lesson] {
                LabOptions options;
                options.scene = *scene;
                options.lesson = *lesson;
                return runLab(options);
            },
            0};
}

int runCommandLine(int argc, char** argv) {
    const ParsedCommandLine parsed = parseCommandLine(argc, argv);
    if (!parsed.action) return parsed.exitStatus;
    try {
        return parsed.action();
    } catch (const RadiantError& e) {
        std::fprintf(stderr, "radiant: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiant: internal error: %s\n", e.what());
        return 1;
    }
}

} // namespace radiant::app
