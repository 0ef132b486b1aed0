#pragma once
// Numbers in messages and metadata: `digits` significant digits, no trailing zeros (printf's %g).
#include <cstdio>
#include <string>

namespace lenslab {

inline std::string formatNumber(double v, int digits = 6) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}

}  // namespace lenslab
