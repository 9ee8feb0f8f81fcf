#pragma once
// The few text colours that carry meaning in every panel: red for what failed, amber for what the
// user should know (a value refused, a fallback taken), green for done.
#include <imgui.h>

namespace radiant::app::theme {

inline const ImVec4 kErrorRed{0.96f, 0.42f, 0.40f, 1.0f};
inline const ImVec4 kWarningAmber{0.95f, 0.75f, 0.35f, 1.0f};
inline const ImVec4 kDoneGreen{0.50f, 0.85f, 0.55f, 1.0f};

} // namespace radiant::app::theme
