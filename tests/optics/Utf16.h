#pragma once
// Text as Windows programs (Zemax, Code V) save it: UTF-16 with a byte order mark.
#include <cstdint>
#include <string>

namespace lenslab::test {

// UTF-8 -> UTF-16 with a byte order mark, little- or big-endian.
inline std::string toUtf16(const std::string& utf8, bool littleEndian) {
    std::string out;
    const auto put = [&](std::uint32_t u) {
        const char hi = char(u >> 8), lo = char(u & 0xff);
        out += littleEndian ? lo : hi;
        out += littleEndian ? hi : lo;
    };
    put(0xfeff);
    for (std::size_t i = 0; i < utf8.size();) {
        const auto b = std::uint8_t(utf8[i]);
        const int extra = b < 0x80 ? 0 : b < 0xe0 ? 1 : b < 0xf0 ? 2 : 3;
        std::uint32_t c = extra == 0 ? b : b & (0x3f >> extra);
        for (int k = 1; k <= extra; ++k) c = (c << 6) | (std::uint8_t(utf8[i + k]) & 0x3f);
        i += extra + 1;
        if (c >= 0x10000) {
            put(0xd800 + ((c - 0x10000) >> 10));
            put(0xdc00 + ((c - 0x10000) & 0x3ff));
        } else {
            put(c);
        }
    }
    return out;
}

}  // namespace lenslab::test
