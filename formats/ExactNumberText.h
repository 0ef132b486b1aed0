#pragma once
// Numbers in prescriptions lenslab writes: the shortest text that reads back as the same double,
// so a written lens parses to exactly the rows it was written from ("50", not "50.000000000000000").
#include <cstdio>
#include <cstdlib>
#include <string>

namespace lenslab {

inline std::string exactNumberText(double v) {
    char b[40];
    for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(b, sizeof b, "%.*g", digits, v);
        if (std::strtod(b, nullptr) == v) break;
    }
    return b;
}

}  // namespace lenslab
