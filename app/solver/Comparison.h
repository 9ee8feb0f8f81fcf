#pragma once
// Two methods side by side (issue #16 item 5): what the second solver ("B") does differently from the
// first ("A"), and how a command sent to A reaches B. Both solve the same scene with the same
// materials, tolerance and view; B differs by its method and, for "one method at two settings", by
// its meshing. GL-free; the main thread owns these values (app/solver/LiveSolve.h).
#include <cstdint>
#include <optional>
#include <string>

#include "app/solver/SolverCommand.h"

namespace radiant::app {

/// What the comparison's 3D view shows.
enum class ComparisonView {
    SideBySide,  ///< A in the left half, B in the right, one camera
    Difference,  ///< per patch of the finer mesh, |B_A - B_B| / B in false colour (SolutionDifference.h)
};

struct ComparisonSettings {
    SolverMethod method = SolverMethod::GaussSeidel;  ///< B's method
    /// B's largest patch area as a multiple of A's: 1 the same mesh, 0.25 a mesh twice as fine.
    double patchAreaScale = 1.0;
    ComparisonView view = ComparisonView::SideBySide;
    bool operator==(const ComparisonSettings&) const = default;
};

/// The patch-area scales the Solver panel offers for B, with their words.
struct PatchAreaChoice {
    double scale;
    const char* label;
};
inline constexpr PatchAreaChoice kPatchAreaChoices[] = {
    {1.0, "same as A"}, {0.25, "finer (1/4 area)"}, {4.0, "coarser (4x area)"}};

/// The command B takes for `command` sent to A, or nullopt when it concerns A alone (SetMethod: B's
/// method is its own). Meshing is scaled by settings.patchAreaScale; a focused point is moved to B's
/// mesh (`secondMeshGeneration`), since a point on the scene is a point on either mesh.
std::optional<SolverCommand> commandForSecond(const SolverCommand& command, const ComparisonSettings& settings,
                                              std::uint64_t secondMeshGeneration);

/// "A" / "B" and the method, for the halves' labels and the plot's legend: "B: Gauss-Seidel, finer mesh".
std::string comparisonLabel(char side, SolverMethod method, double patchAreaScale);

} // namespace radiant::app
