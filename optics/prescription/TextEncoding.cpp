#include "prescription/TextEncoding.h"

#include <cctype>
#include <cstdint>

#include "prescription/LensTable.h"

namespace lenslab {

namespace {

const std::string kUtf8Mark = "\xef\xbb\xbf";

void appendUtf8(std::string& out, std::uint32_t c) {
    if (c < 0x80) {
        out += char(c);
    } else if (c < 0x800) {
        out += char(0xc0 | (c >> 6));
        out += char(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        out += char(0xe0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3f));
        out += char(0x80 | (c & 0x3f));
    } else {
        out += char(0xf0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3f));
        out += char(0x80 | ((c >> 6) & 0x3f));
        out += char(0x80 | (c & 0x3f));
    }
}

std::string utf16ToUtf8(const std::string& bytes, bool littleEndian, const std::string& name) {
    const auto unit = [&](std::size_t i) {
        const auto a = std::uint8_t(bytes[i]), b = std::uint8_t(bytes[i + 1]);
        return std::uint32_t(littleEndian ? a | (b << 8) : (a << 8) | b);
    };
    std::string out;
    out.reserve(bytes.size() / 2);
    int line = 1;  // lines counted as they are decoded, so an error names the file's line
    if (bytes.size() % 2 != 0) {
        for (std::size_t i = 2; i + 1 < bytes.size(); i += 2) line += unit(i) == '\n';
        throw LensTableError(name, line, "UTF-16 text with an odd number of bytes (" +
                                             std::to_string(bytes.size()) + "): the file is cut short or not UTF-16");
    }
    for (std::size_t i = 2; i < bytes.size(); i += 2) {
        std::uint32_t c = unit(i);
        if (c >= 0xdc00 && c <= 0xdfff)
            throw LensTableError(name, line, "broken UTF-16: a low surrogate without a high one");
        if (c >= 0xd800 && c <= 0xdbff) {
            const std::uint32_t low = i + 2 < bytes.size() ? unit(i + 2) : 0;
            if (low < 0xdc00 || low > 0xdfff)
                throw LensTableError(name, line, "broken UTF-16: a high surrogate without a low one");
            c = 0x10000 + ((c - 0xd800) << 10) + (low - 0xdc00);
            i += 2;
        }
        line += c == '\n';
        appendUtf8(out, c);
    }
    return out;
}

}  // namespace

bool startsWithUtf16ByteOrderMark(const std::string& bytes) {
    return bytes.rfind("\xff\xfe", 0) == 0 || bytes.rfind("\xfe\xff", 0) == 0;
}

std::string toUtf8Text(const std::string& bytes, const std::string& name) {
    if (startsWithUtf16ByteOrderMark(bytes)) return utf16ToUtf8(bytes, bytes[0] == '\xff', name);
    if (bytes.rfind(kUtf8Mark, 0) == 0) return bytes.substr(kUtf8Mark.size());
    return bytes;
}

std::string upperCase(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace lenslab
