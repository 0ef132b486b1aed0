#pragma once
// Numbers in prescriptions lenslab writes: the shortest text that reads back as the same double,
// so a written lens parses to exactly the rows it was written from ("50", not "50.000000000000000").
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace lenslab {

inline std::string exactNumberText(double v) {
    char b[40];
    for (int digits = 15; digits <= std::numeric_limits<double>::max_digits10; ++digits) {
        std::snprintf(b, sizeof b, "%.*g", digits, v);
        if (std::strtod(b, nullptr) == v) break;
    }
    return b;
}

// 1 / r as text from which the reciprocal, taken in long double as lenslab's .zmx reader takes it,
// rounds back to r: a radius written as a curvature (CURV) reads back exactly. A double curvature
// cannot do that for every radius (1 / (1 / r) is one ulp off for some); long double's extra bits
// can, given its max_digits10 digits. The shortest such text is written.
inline std::string exactReciprocalText(double r) {
    const long double c = 1.0L / r;
    char b[48];
    for (int digits = 15; digits <= std::numeric_limits<long double>::max_digits10; ++digits) {
        std::snprintf(b, sizeof b, "%.*Lg", digits, c);
        if (static_cast<double>(1.0L / std::strtold(b, nullptr)) == r) break;
    }
    return b;
}

// v / 1000 as the text of v with its decimal point moved three places left ("587.5618" ->
// "0.5875618"): a wavelength in nm written in micrometres (WAVM). Read back with the exponent raised
// by 3 (optics/prescription/ZemaxFile.cpp) it is v exactly, which no double v / 1000 is for every v.
inline std::string exactThousandthText(double v) {
    const std::string text = exactNumberText(v);
    if (text.find_first_of("eEni") != std::string::npos) return text + "e-3";  // exponent form, inf, nan
    const bool negative = text[0] == '-';
    const std::string body = text.substr(negative ? 1 : 0);
    const auto point = body.find('.');
    const std::string whole = body.substr(0, point), digits = whole + (point == std::string::npos ? "" : body.substr(point + 1));
    const long split = long(whole.size()) - 3;
    std::string out = split > 0 ? digits.substr(0, split) + "." + digits.substr(split)
                                : "0." + std::string(-split, '0') + digits;
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
    return (negative ? "-" : "") + out;
}

}  // namespace lenslab
