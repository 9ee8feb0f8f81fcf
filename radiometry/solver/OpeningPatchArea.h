#pragma once
// The largest patch area the lab opens a scene at: the finest step from the default
// (kSolveDefaults.maxPatchArea) up at which the scene meshes into no more patches than progressive
// refinement, the small meshes' default method, is chosen for (kProgressiveMaxPatches, 3,000: a
// solve of a second or so; the Cornell box is 2,248 at the default). So the Cornell box and anything
// smaller open at the default, and a room opens at about that count rather than at the default: a
// 57 m^2 room opened as 61,935 patches at 10 cm^2 and hierarchical sweeps of half a minute. (Until
// session 23 the budget was the Cornell box's own count, 2,805, which its finer meshing along the
// blocks' feet and coarser default brought down.) The command line keeps --max-patch-area's default.
#include <string>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct OpeningArea {
    double maxPatchArea = 0;  ///< m^2
    /// For people: "250 cm^2 for the scene's 57.1 m^2: 2,694 patches, ...".
    std::string reason;
};

/// The steps are 1, 2, 2.5 and 5 times a power of ten cm^2, up to kMaxOpeningPatchArea, the
/// coarsest (a scene too large for the budget even there opens at it).
[[nodiscard]] OpeningArea openingPatchArea(const Scene& scene);

/// m^2: the coarsest opening, the Scene panel's slider's end (2,500 cm^2).
inline constexpr double kMaxOpeningPatchArea = 0.25;

} // namespace radiant
