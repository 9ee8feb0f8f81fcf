#pragma once
// The `radiant probe ...` line that repeats a lab reading on the command line: the lab's "Copy as
// command" puts it on the clipboard, so a teaching assistant's answer key reads the same point with
// the same method, mesh and tolerance. Numbers are written to round-trip (the shortest text that
// reads back as the same double), so the point is the lab's to the last bit.
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "radiometry/solver/SolverMethods.h"

namespace radiant::app {

struct ProbeCommandInputs {
    std::string scene;  ///< built-in name or glTF path, as Scene::name holds it
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0, 0, 1};
    std::optional<std::string> target;  ///< surface name; none: probe's default (the first emitter)
    SolverMethod method = SolverMethod::GaussSeidel;
    double maxPatchArea = 0;  ///< m^2
    double tolerance = 0;
    std::optional<double> linkTolerance;  ///< hierarchical and importance methods
};

/// "radiant probe SCENE --point=X,Y,Z --normal=X,Y,Z [--target=NAME] --method=... ..." for a POSIX
/// shell: the scene path made absolute (the command may run elsewhere), words quoted where needed.
[[nodiscard]] std::string probeCommandLine(const ProbeCommandInputs& inputs);

/// The shortest text that reads back as the same double ("0.1", "-3.0000000000000004").
[[nodiscard]] std::string roundTripNumber(double value);
/// "X,Y,Z" with roundTripNumber, as --point and --normal read it.
[[nodiscard]] std::string roundTripVector(const glm::dvec3& v);
/// The word as one POSIX shell word: unchanged when safe, else in single quotes.
[[nodiscard]] std::string shellQuoted(std::string_view word);

} // namespace radiant::app
