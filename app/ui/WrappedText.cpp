#include "app/ui/WrappedText.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <string>

namespace radiant::app::ui {
namespace {

std::string_view withoutTrailingSpaces(std::string_view piece) {
    while (!piece.empty() && piece.back() == ' ') piece.remove_suffix(1);
    return piece;
}

/// Whether the word ending just before `end` is a number ("2,335", "0.025", "(250", "-3"; not "m^2").
bool numberEndsAt(std::string_view paragraph, std::size_t end) {
    if (end == 0 || !std::isdigit(static_cast<unsigned char>(paragraph[end - 1]))) return false;
    std::size_t start = paragraph.rfind(' ', end - 1);
    start = start == std::string_view::npos ? 0 : start + 1;
    while (start < end && (paragraph[start] == '(' || paragraph[start] == '-' || paragraph[start] == '+')) ++start;
    return start < end && (std::isdigit(static_cast<unsigned char>(paragraph[start])) || paragraph[start] == '.');
}

/// The first space at or after `from` where a line may break: not one after a number, so that a
/// number stays with its unit or the word it counts ("0.025 m^2", "2,335 groups").
std::size_t nextBreak(std::string_view paragraph, std::size_t from) {
    for (std::size_t at = paragraph.find(' ', from); at != std::string_view::npos; at = paragraph.find(' ', at + 1))
        if (!numberEndsAt(paragraph, at)) return at;
    return paragraph.size();
}

} // namespace

std::vector<std::string_view> breakAtSpaces(std::string_view text, float width,
                                            const std::function<float(std::string_view)>& measure) {
    std::vector<std::string_view> lines;
    std::size_t paragraphStart = 0;
    while (paragraphStart <= text.size()) {
        std::size_t paragraphEnd = text.find('\n', paragraphStart);
        if (paragraphEnd == std::string_view::npos) paragraphEnd = text.size();
        const std::string_view paragraph = text.substr(paragraphStart, paragraphEnd - paragraphStart);

        std::size_t lineStart = 0;
        while (true) {
            // Grow the line word by word while it fits; the first word always goes on.
            std::size_t lineEnd = nextBreak(paragraph, lineStart);
            while (lineEnd < paragraph.size()) {
                const std::size_t next = nextBreak(paragraph, lineEnd + 1);
                if (measure(withoutTrailingSpaces(paragraph.substr(lineStart, next - lineStart))) > width) break;
                lineEnd = next;
            }
            const std::string_view line = withoutTrailingSpaces(paragraph.substr(lineStart, lineEnd - lineStart));
            if (measure(line) > width) {
                // One word wider than the line (a file's path): cut it where it stops fitting, on a
                // UTF-8 character's first byte, at least one character a line.
                std::size_t cut = 1;
                while (cut < line.size() && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) ++cut;
                for (std::size_t next = cut; next < line.size();) {
                    ++next;
                    while (next < line.size() && (static_cast<unsigned char>(line[next]) & 0xC0) == 0x80) ++next;
                    if (measure(line.substr(0, next)) > width) break;
                    cut = next;
                }
                if (cut < line.size()) {
                    lines.push_back(withoutTrailingSpaces(line.substr(0, cut)));
                    lineStart += cut;
                    while (lineStart < paragraph.size() && paragraph[lineStart] == ' ') ++lineStart;
                    continue;
                }
            }
            lines.push_back(line);
            if (lineEnd >= paragraph.size()) break;
            lineStart = lineEnd + 1;
            while (lineStart < paragraph.size() && paragraph[lineStart] == ' ') ++lineStart;
            if (lineStart >= paragraph.size()) break;
        }
        if (paragraphEnd == text.size()) break;
        paragraphStart = paragraphEnd + 1;
    }
    return lines;
}

std::string withSuperscriptSquares(std::string_view text) {
    std::string shown;
    shown.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '^' && i + 1 < text.size() && text[i + 1] == '2' && i > 0 &&
            std::isalpha(static_cast<unsigned char>(text[i - 1])) &&
            (i + 2 == text.size() || !std::isdigit(static_cast<unsigned char>(text[i + 2])))) {
            shown += "\xC2\xB2";
            ++i;
        } else {
            shown += text[i];
        }
    }
    return shown;
}

void wrappedTextUnformatted(std::string_view unitsInAscii) {
    const std::string text = withSuperscriptSquares(unitsInAscii);
    // The width ImGui::TextWrapped would use: a pushed wrap position (a tooltip's), else the
    // content region's right edge.
    const float wrapPosition = std::max(ImGui::GetCurrentWindow()->DC.TextWrapPos, 0.0f);
    const float width = ImGui::CalcWrapWidthForPos(ImGui::GetCursorScreenPos(), wrapPosition);
    const auto measure = [](std::string_view piece) {
        return ImGui::CalcTextSize(piece.data(), piece.data() + piece.size()).x;
    };
    for (const std::string_view line : breakAtSpaces(text, width, measure))
        ImGui::TextUnformatted(line.data(), line.data() + line.size());
}

namespace {

std::string formatted(const char* format, std::va_list arguments) {
    std::va_list copy;
    va_copy(copy, arguments);
    const int length = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string text(length > 0 ? static_cast<std::size_t>(length) : 0, '\0');
    if (length > 0) std::vsnprintf(text.data(), text.size() + 1, format, arguments);
    return text;
}

} // namespace

void wrappedText(const char* format, ...) {
    std::va_list arguments;
    va_start(arguments, format);
    const std::string text = formatted(format, arguments);
    va_end(arguments);
    wrappedTextUnformatted(text);
}

void wrappedTextColoured(const ImVec4& colour, std::string_view text) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    wrappedTextUnformatted(text);
    ImGui::PopStyleColor();
}

void wrappedTextDisabled(const char* format, ...) {
    std::va_list arguments;
    va_start(arguments, format);
    const std::string text = formatted(format, arguments);
    va_end(arguments);
    wrappedTextColoured(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), text);
}

} // namespace radiant::app::ui
