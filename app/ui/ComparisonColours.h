#pragma once
// The two sides of the comparison mode (app/solver/Comparison.h) in one colour each, shared by the
// halves' labels and the convergence plot's curves: orange for A, sky blue for B (the first two of
// Okabe & Ito's palette, told apart with any colour vision and on a projector).
#include <imgui.h>

namespace radiant::app::theme {

inline constexpr ImU32 kSideA = IM_COL32(230, 159, 0, 255);
inline constexpr ImU32 kSideB = IM_COL32(86, 180, 233, 255);

} // namespace radiant::app::theme
