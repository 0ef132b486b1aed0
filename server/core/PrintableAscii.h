#pragma once
// Printable ASCII (space to tilde): names that cannot pass for another (a fullwidth "ＳＣＨＯＴＴ", or
// "SCHOTT" with an invisible zero-width space, reads as SCHOTT and is not it).
#include <algorithm>
#include <string>

namespace lenslab {

inline bool isPrintableAscii(const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c >= ' ' && c <= '~'; });
}

}  // namespace lenslab
