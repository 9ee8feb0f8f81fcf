#pragma once
// The largest patch area the lab opens a scene at: the finest step from the default
// (kSolveDefaults.maxPatchArea) up at which the scene meshes into no more patches than the Cornell
// box does at the default (2,805: progressive refinement, a solve of a second or so). So the Cornell
// box and anything smaller open as before, and a room opens at about the Cornell box's patch count
// rather than at 10 cm^2: a 57 m^2 room opened as 61,935 patches and hierarchical sweeps of half a
// minute. The command line keeps --max-patch-area's default.
#include <string>

#include "radiometry/scene/Scene.h"

namespace radiant {

struct OpeningArea {
    double maxPatchArea = 0;  ///< m^2
    /// For people: "250 cm^2 for the scene's 57.1 m^2: 2,694 patches, ...".
    std::string reason;
};

/// The steps are 1, 2, 2.5 and 5 times a power of ten cm^2, up to kMaxOpeningPatchArea, the
/// coarsest (a scene too large for the Cornell box's count even there opens at it).
[[nodiscard]] OpeningArea openingPatchArea(const Scene& scene);

/// m^2: the coarsest opening, the Scene panel's slider's end (2,500 cm^2).
inline constexpr double kMaxOpeningPatchArea = 0.25;

} // namespace radiant
