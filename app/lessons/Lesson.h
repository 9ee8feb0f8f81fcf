#pragma once
// A lesson: steps a lecturer pages through, each with a caption and the actions that set the lab up
// for it (docs/lessons.md is the format). Plain values, GL-free: the command line checks a lesson
// file without a window, and the lab plays the same values.
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/solver/Comparison.h"
#include "radiometry/solver/SolverMethods.h"

namespace radiant::app::lesson {

using Triple = std::array<double, 3>;

/// A built-in scene's name, or a glTF path (resolved against the lesson file's folder).
struct LoadScene {
    std::string scene;
};
/// One of the lecture demos (LectureDemos.h), by its id: "point-source", "sun", ...
struct OpenDemo {
    std::string demo;
};
struct SetMethod {
    SolverMethod method;
};
struct SetTolerance {
    double tolerance;  ///< of the method's convergence measure (a fraction of the emitted power)
};
struct SetMeshing {
    double maxPatchAreaM2;
};
struct SetLinkTolerance {
    double linkTolerance;
};
struct SetMaterial {
    std::string surface;
    std::optional<Triple> reflectance;   ///< per band, [0, 1)
    std::optional<Triple> exitanceW_m2;  ///< per band, >= 0
};
/// The scene's home view when `home`, else eye and target in metres and a vertical field of view.
struct PlaceCamera {
    bool home = false;
    Triple eye{};
    Triple target{};
    double fieldOfViewDegrees = 0;
};
struct Run {};
struct Pause {};
struct Reset {};
struct Step {
    std::size_t count;
};
/// The probe's point (on a surface of the current scene), its normal (the surface's when absent)
/// and a target surface for solid angle and form factor.
struct Probe {
    Triple point{};
    std::optional<Triple> normal;
    std::optional<std::string> target;
};
/// Expands a sidebar panel by its title ("Probe", "Hemisphere", ...) and collapses the others.
struct OpenPanel {
    std::string panel;
};
/// The Display panel's settings a step may change; absent fields stay as they are.
struct SetDisplay {
    std::optional<std::string> colour;  ///< "tone-mapped", "false-colour" or "reflectance"
    std::optional<bool> links;
    std::optional<bool> importance;
    std::optional<bool> wireframe;
    std::optional<bool> isolines;
    std::optional<double> exposureStops;
    std::optional<bool> photometric;  ///< lx and cd/m^2 instead of W/m^2
};
/// The Integrals panel's hemisphere integral (IntegralsPanel.h): the geometric integrands, whose
/// exact values need no solve, by one of its three estimators, started when `run`.
struct SetIntegrals {
    std::string integrand;              ///< "d-omega" (2 pi sr) or "cos-d-omega" (pi sr)
    std::string method;                 ///< "riemann", "uniform-mc" or "cosine-mc"
    std::optional<int> thetaCells;      ///< Riemann: the grid's theta cells, 2 to 64 (the panel's slider)
    bool run = false;
};
/// Two methods side by side (app/solver/Comparison.h): B's method, its mesh and the view; none ends
/// the comparison.
struct Compare {
    std::optional<ComparisonSettings> settings;
};

using Action = std::variant<LoadScene, OpenDemo, SetMethod, SetTolerance, SetMeshing, SetLinkTolerance, SetMaterial,
                            PlaceCamera, Run, Pause, Reset, Step, Probe, OpenPanel, SetDisplay, Compare, SetIntegrals>;

struct LessonStep {
    std::string title;
    std::string caption;  ///< a few lines; inline math as plain text
    std::vector<Action> actions;
};

struct Lesson {
    std::string title;
    /// A saved session (SessionFile.h): one step that restores the lab, played without a caption.
    bool session = false;
    std::filesystem::path file;  ///< where it was read from; relative scene paths resolve against its folder
    std::vector<LessonStep> steps;
};

/// The sidebar panels and demos a lesson may name (what the lab shows under those titles and ids).
const std::vector<std::string>& panelTitles();
const std::vector<std::string>& demoIds();

/// The lessons that ship in <assets>/lessons, in file order (their names are numbered); empty when
/// the folder is missing.
std::vector<std::filesystem::path> shippedLessonFiles();

/// Reads and checks a lesson file: JSON syntax, every field's type and range, every scene loads,
/// every named surface exists in the scene current at that step, every probe point lies on one of
/// its surfaces. Throws RadiantError naming the file, the step (number and title), the action and
/// the field, in one line.
Lesson readLesson(const std::filesystem::path& file);
/// The same for text already read (tests, fuzzing); `file` names it in messages and anchors paths.
Lesson parseLesson(const std::string& text, const std::filesystem::path& file);

} // namespace radiant::app::lesson
