#pragma once
// Wrapped sidebar text that breaks lines at spaces only. ImGui's own wrapping (TextWrapped) may break
// after a comma or a full stop inside a word, which splits the thousands of "2,335 groups" over two
// lines and "0.25" after its point; a reader of a projected panel takes "2," and "335" for two numbers.
#include <functional>
#include <imgui.h>

#include <string>
#include <string_view>
#include <vector>

namespace radiant::app::ui {

/// The lines of `text` no wider than `width` as `measure` gives widths, broken at spaces (spaces at
/// a break are dropped) and at '\n', but never at a space after a number (a number stays with its unit
/// or the word it counts). Only a word wider than a whole line (a long file path) is cut
/// inside, where it stops fitting.
std::vector<std::string_view> breakAtSpaces(std::string_view text, float width,
                                            const std::function<float(std::string_view)>& measure);

/// `text` with "m^2" (a letter, then ^2) written m\u00b2, as the sidebar's own numbers are: the
/// reasons and messages the lab shows are the commands' ASCII lines.
std::string withSuperscriptSquares(std::string_view text);

/// As ImGui::TextWrapped (printf format, wrapped where TextWrapped would), but through breakAtSpaces
/// and withSuperscriptSquares. UI thread, inside a window.
void wrappedText(const char* format, ...);

/// wrappedText in the theme's dimmed colour, as ImGui::TextDisabled: the reasons and notes under a
/// control, which say why rather than what.
void wrappedTextDisabled(const char* format, ...);

/// `text` as it is, wrapped as wrappedText does.
void wrappedTextUnformatted(std::string_view text);

/// wrappedTextUnformatted in `colour` (an error's red, a warning's amber).
void wrappedTextColoured(const ImVec4& colour, std::string_view text);

} // namespace radiant::app::ui
