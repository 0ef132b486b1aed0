#pragma once
// Numbers as lenslab writes them in messages, metadata, diagrams, tables and the report: one
// formatter per style, shared by every part.
#include <cmath>
#include <cstdio>
#include <string>

namespace lenslab {

// `digits` significant digits, no trailing zeros (printf's %g).
inline std::string formatNumber(double v, int digits = 6) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}

// `decimals` digits after the point; a value that rounds to zero keeps no sign; "–" for NaN and
// infinities.
inline std::string formatFixed(double v, int decimals) {
    if (!std::isfinite(v)) return "\u2013";
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    std::string s = b;
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

// A length in millimetres as messages state it: "12.5 mm".
inline std::string formatMillimetres(double v) { return formatNumber(v) + " mm"; }

// An f-number as lenses are marked: three significant digits (2.02, 5.6), whole numbers from
// 1000 on.
inline std::string formatFNumber(double v) { return std::fabs(v) >= 1000 ? formatFixed(v, 0) : formatNumber(v, 3); }

}  // namespace lenslab
