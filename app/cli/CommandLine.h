#pragma once
// `radiant [SCENE]` opens the lab; `radiant solve|probe|reference|render|bench ...` run without a window.
// Exit status 0 on success, 2 on bad arguments or bad input (one line on stderr).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchGroups.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/DefaultGrouping.h"
#include "radiometry/solver/DefaultMethod.h"
#include "radiometry/solver/Solver.h"

namespace CLI {
class App;
}

namespace radiant::app {

int runCommandLine(int argc, char** argv);

/// Each subcommand lives in its own file and registers its options and its action here.
using CommandAction = std::function<int()>;

/// The command line parsed and not yet acted on, so the parser can be tested (and fuzzed) without
/// opening windows or solving scenes. The action owns the parsed values it needs.
struct ParsedCommandLine {
    CommandAction action;  ///< the chosen subcommand, or the lab; empty when parsing ended the run
    int exitStatus = 0;    ///< when there is no action: 0 after --help, 2 after bad arguments
};
/// Parses argv (prints help or the one-line error itself); never runs a command.
ParsedCommandLine parseCommandLine(int argc, const char* const* argv);
struct Subcommand {
    CLI::App* app = nullptr;
    CommandAction run;
};
/// The SCENE argument of every subcommand (a built-in name or a glTF path), its loader warnings
/// printed on stderr, one line each. Throws RadiantError as loadScene does.
Scene loadSceneArgument(const std::string& nameOrPath);

/// --group-patches and --no-group-patches of solve, probe and render (DefaultGrouping.h).
struct GroupingFlags {
    bool on = false;
    bool off = false;
    [[nodiscard]] GroupingMode mode() const { return on ? GroupingMode::On : off ? GroupingMode::Off : GroupingMode::Auto; }
};
/// Adds the two flags; `what` ends the --group-patches help ("; each patch drawn with its group's B").
void addGroupingFlags(CLI::App& sub, GroupingFlags& flags, const std::string& what = "");

/// What solve, probe and render solve: the mesh at --max-patch-area, its patch groups and the
/// method, as chooseSystem decides them (DefaultGrouping.h). Where patches are grouped, a named
/// method declines them, or --group-patches asked, the grouping and its reason are said on stderr
/// in one line ("radiant: grouping: on: ..."); a defaulted method in another ("radiant: method:
/// hierarchical (12,000 patches: ...)").
struct CommandSystem {
    /// The scene's ray caster, built once for the mesher (covered pieces) and the solver, as the
    /// lab's solver thread shares one: two BVHs of the Cornell box cost the command ~15 ms.
    std::shared_ptr<const RayCaster> rays;
    PatchMesh mesh;
    std::shared_ptr<const PatchGroups> groups;  ///< null: every patch an unknown
    std::string groupingReason;
    MethodChoice choice;  ///< the reason is empty for a named method
};
CommandSystem meshForCommand(const std::string& namedMethod, const Scene& scene, double maxPatchArea, GroupingMode grouping);
/// The system's solver (grouped or not); a budget refusal that names no file names the scene.
std::unique_ptr<Solver> makeCommandSolver(const Scene& scene, const CommandSystem& system, const SolverOptions& options,
                                          Progress* progress = nullptr);
/// The --method help: the names and how the default is chosen.
std::string methodOptionHelp();

/// Writes `text` to `path`, or to standard output for "-"; a file that cannot be written is a
/// RadiantError naming it and the option it came from.
void writeText(const std::string& path, const std::string& text, const char* option);

Subcommand addSolveCommand(CLI::App& root);
Subcommand addProbeCommand(CLI::App& root);
Subcommand addReferenceCommand(CLI::App& root);
Subcommand addRenderCommand(CLI::App& root);
Subcommand addBenchCommand(CLI::App& root);
Subcommand addLessonCommand(CLI::App& root);

} // namespace radiant::app
