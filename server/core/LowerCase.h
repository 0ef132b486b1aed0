#pragma once
// ASCII lower case: HTTP header names and tokens compare without regard to case (RFC 9110 5.1).
#include <algorithm>
#include <cctype>
#include <string>

namespace lenslab {

inline std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

}  // namespace lenslab
