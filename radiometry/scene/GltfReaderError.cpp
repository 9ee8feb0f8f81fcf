#include "radiometry/scene/GltfReaderError.h"

namespace radiant::detail {
namespace {

std::string withoutLineBreaks(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    for (std::size_t at = text.find_first_of("\r\n"); at != std::string::npos; at = text.find_first_of("\r\n", at))
        text.replace(at, 1, "; ");
    return text;
}

/// "[json.exception.parse_error.101] parse error at line 2, column 9: <why>; last read: '<token>'"
/// becomes "malformed JSON at line 2, column 9, after '...<last 16 of token>': <why>": the place
/// first, so a cut to length loses the end of the reason, never where it is.
std::string shortenJsonParseError(std::string text) {
    if (text.rfind("[json.exception.", 0) == 0) {
        const std::size_t close = text.find("] ");
        if (close != std::string::npos) text.erase(0, close + 2);
    }
    if (text.rfind("parse error ", 0) == 0) text.replace(0, 12, "malformed JSON ");
    const std::string lastRead = "; last read: '";
    const std::size_t quoted = text.find(lastRead);
    const std::size_t colon = text.find(": ");
    if (quoted == std::string::npos || colon == std::string::npos || colon > quoted) return text;
    std::string token = text.substr(quoted + lastRead.size());
    if (!token.empty() && token.back() == '\'') token.pop_back();
    constexpr std::size_t kTokenTail = 16;
    if (token.size() > kTokenTail) token = "..." + token.substr(token.size() - kTokenTail);
    return text.substr(0, colon) + ", after '" + token + "'" + text.substr(colon, quoted - colon);
}

} // namespace

std::string gltfReaderErrorLine(const std::string& readerError, std::size_t maxLength) {
    std::string text = withoutLineBreaks(shortenJsonParseError(readerError));
    if (text.empty()) return "not a glTF file";
    if (text.size() > maxLength) {
        const std::string ellipsis = "...";
        std::size_t keep = maxLength > ellipsis.size() ? maxLength - ellipsis.size() : 0;
        while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0u) == 0x80u) --keep;  // whole UTF-8 characters
        text.resize(keep);
        text += ellipsis;
    }
    return text;
}

} // namespace radiant::detail
