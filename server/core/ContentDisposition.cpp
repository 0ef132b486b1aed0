#include "core/ContentDisposition.h"

#include <cctype>

namespace lenslab {

namespace {

bool isSeparatorOrControl(unsigned char c) { return c < 0x20 || c == 0x7f || c == '/' || c == '\\'; }

// RFC 8187's attr-char: what filename* carries unencoded.
bool isAttributeCharacter(unsigned char c) {
    return std::isalnum(c) || std::string("!#$&+-.^_`|~").find(char(c)) != std::string::npos;
}

}  // namespace

std::string attachmentDisposition(const std::string& fileName) {
    static const char* const kHex = "0123456789ABCDEF";
    std::string plain, encoded;
    for (const char ch : fileName) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (isSeparatorOrControl(c)) {
            plain += '_';
            encoded += '_';
            continue;
        }
        // Inside the quotes: letters, digits and the punctuation no client reads as syntax; one '_'
        // for each other character (a UTF-8 sequence's continuation bytes add none).
        if (c < 0x80 && (std::isalnum(c) || std::string(" ._-+()").find(ch) != std::string::npos)) plain += ch;
        else if (c < 0x80 || c >= 0xc0) plain += '_';
        if (isAttributeCharacter(c)) encoded += ch;
        else encoded += std::string("%") + kHex[c >> 4] + kHex[c & 15];
    }
    return "attachment; filename=\"" + plain + "\"; filename*=UTF-8''" + encoded;
}

}  // namespace lenslab
