#include "LineText.h"

#include <cstdint>
#include <cstdio>

namespace lenslab {

namespace {

// The code point of the UTF-8 sequence at `at` and its length; length 0 when malformed.
std::pair<std::uint32_t, std::size_t> codePointAt(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) return {lead, 1};
    const std::size_t length = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc2 ? 2 : 0;
    if (length == 0 || lead > 0xf4 || at + length > text.size()) return {0, 0};
    std::uint32_t code = lead & (0x7f >> length);
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xc0) != 0x80) return {0, 0};
        code = (code << 6) | (byte(at + i) & 0x3f);
    }
    const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || (code >= 0xd800 && code <= 0xdfff) || code > 0x10ffff) return {0, 0};
    return {code, length};
}

std::string codePointName(std::uint32_t code) {
    char b[16];
    std::snprintf(b, sizeof b, "U+%04X", static_cast<unsigned>(code));
    return b;
}

}  // namespace

std::optional<std::string> lineTextProblem(const std::string& text) {
    for (std::size_t at = 0; at < text.size();) {
        const auto [code, length] = codePointAt(text, at);
        if (length == 0) return "malformed UTF-8 at byte " + std::to_string(at + 1);
        // C0 controls but tab (line feed, carriage return, vertical tab, form feed, ...), DEL, the C1
        // controls (next line U+0085 among them), and the line and paragraph separators.
        if ((code < 0x20 && code != '\t') || (code >= 0x7f && code <= 0x9f) || code == 0x2028 || code == 0x2029)
            return "a control character or line break (" + codePointName(code) + ") at byte " + std::to_string(at + 1);
        at += length;
    }
    return std::nullopt;
}

std::optional<std::string> wordTextProblem(const std::string& text) {
    if (text.empty()) return std::string("an empty name");
    if (text.find_first_of(" \t") != std::string::npos) return std::string("a space inside the name");
    return lineTextProblem(text);
}

}  // namespace lenslab
