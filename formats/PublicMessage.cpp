#include "PublicMessage.h"

#include <cstring>

namespace lenslab {

namespace {

// A message longer than this (a long list of short words quoted from the input) is cut too.
constexpr std::size_t kMaxMessageBytes = 1000;

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Characters that end a path in a message: "file.dat:3: ...", "(/x/y)", "'/x/y'", "/x/y, ...".
bool endsPath(char c) { return isSpace(c) || std::strchr("'\"():,;", c) != nullptr; }

// A '/' that begins a path: at the start, or after a space, quote, parenthesis or '='.
bool beginsPath(const std::string& text, std::size_t at) {
    return text[at] == '/' && (at == 0 || isSpace(text[at - 1]) || std::strchr("'\"(=", text[at - 1]) != nullptr);
}

bool isServiceUrl(const std::string& path) { return path.rfind("/api/", 0) == 0 || path.rfind("/report/", 0) == 0; }

// Paths of two or more segments, the service's own URLs aside, as their last segment.
std::string withFileNames(const std::string& text) {
    std::string out;
    for (std::size_t at = 0; at < text.size();) {
        if (!beginsPath(text, at)) {
            out += text[at++];
            continue;
        }
        std::size_t end = at;
        while (end < text.size() && !endsPath(text[end])) ++end;
        const std::string path = text.substr(at, end - at);
        std::string name = path;
        while (name.size() > 1 && name.back() == '/') name.pop_back();
        const std::size_t slash = name.find_last_of('/');
        out += slash == 0 || isServiceUrl(path) ? path : name.substr(slash + 1);
        at = end;
    }
    return out;
}

bool continuesCharacter(char c) { return (static_cast<unsigned char>(c) & 0xc0) == 0x80; }

// A quote that opens a value: at the start, or after a space, parenthesis, '=' or ':' (an
// apostrophe inside a word, as in "lens's", opens nothing).
bool opensQuote(const std::string& text, std::size_t at) {
    return (text[at] == '\'' || text[at] == '"') &&
           (at == 0 || isSpace(text[at - 1]) || std::strchr("(=:[", text[at - 1]) != nullptr);
}

// Each quoted value, and each word outside quotes, cut at kShownValueCharacters (whole UTF-8
// characters).
std::string withShortValues(const std::string& text) {
    std::string out;
    std::size_t shown = 0;  // characters of the current word or quoted value
    char quote = 0;         // the quote of the value being copied; 0 outside quotes
    bool cut = false;
    for (std::size_t at = 0; at < text.size(); ++at) {
        const char c = text[at];
        const bool opens = !quote && opensQuote(text, at);
        const bool ends = quote ? c == quote : isSpace(c);
        if (opens || ends) {
            quote = opens ? c : ends && quote ? 0 : quote;
            shown = 0;
            cut = false;
            out += c;
            continue;
        }
        if (cut) continue;
        if (!continuesCharacter(c) && ++shown > kShownValueCharacters) {
            out += "\u2026";
            cut = true;
            continue;
        }
        out += c;
    }
    return out;
}

}  // namespace

std::string publicMessage(const std::string& message) {
    std::string text = message;
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    std::string shown = withShortValues(withFileNames(text));
    if (shown.size() > kMaxMessageBytes) {
        std::size_t end = kMaxMessageBytes;
        while (end > 0 && continuesCharacter(shown[end])) --end;
        shown = shown.substr(0, end) + "\u2026";
    }
    return shown;
}

}  // namespace lenslab
