#include "core/SmitsSpectrum.h"

#include <algorithm>
#include <cmath>

#include "core/TabulatedSpectrum.h"

namespace lenslab {

namespace {

// Smits (1999), table 1: white, cyan, magenta, yellow, red, green, blue at 10 wavelengths.
constexpr double kBases[kSmitsBases][10] = {
    {1.0000, 1.0000, 0.9999, 0.9993, 0.9992, 0.9998, 1.0000, 1.0000, 1.0000, 1.0000},
    {0.9710, 0.9426, 1.0007, 1.0007, 1.0007, 1.0007, 0.1564, 0.0000, 0.0000, 0.0000},
    {1.0000, 1.0000, 0.9685, 0.2229, 0.0000, 0.0458, 0.8369, 1.0000, 1.0000, 0.9959},
    {0.0001, 0.0000, 0.1088, 0.6651, 1.0000, 1.0000, 0.9996, 0.9586, 0.9685, 0.9840},
    {0.1012, 0.0515, 0.0000, 0.0000, 0.0000, 0.0000, 0.8325, 1.0149, 1.0149, 1.0149},
    {0.0000, 0.0000, 0.0273, 0.7937, 1.0000, 0.9418, 0.1719, 0.0000, 0.0000, 0.0025},
    {1.0000, 1.0000, 0.8916, 0.3323, 0.0000, 0.0000, 0.0003, 0.0369, 0.0483, 0.0496},
};
constexpr double kSmitsFirstNm = 380, kSmitsLastNm = 720;

}  // namespace

std::array<float, kSmitsBases> smitsCoefficients(const Vec3f& c) {
    std::array<float, kSmitsBases> k{};
    const auto at = [&](SmitsBasis b) -> float& { return k[int(b)]; };
    if (c.x <= c.y && c.x <= c.z) {  // red smallest: white, then cyan, then green or blue
        at(SmitsBasis::White) = c.x;
        at(SmitsBasis::Cyan) = std::min(c.y, c.z) - c.x;
        (c.y <= c.z ? at(SmitsBasis::Blue) : at(SmitsBasis::Green)) = std::fabs(c.z - c.y);
    } else if (c.y <= c.x && c.y <= c.z) {  // green smallest: white, magenta, red or blue
        at(SmitsBasis::White) = c.y;
        at(SmitsBasis::Magenta) = std::min(c.x, c.z) - c.y;
        (c.x <= c.z ? at(SmitsBasis::Blue) : at(SmitsBasis::Red)) = std::fabs(c.z - c.x);
    } else {  // blue smallest: white, yellow, red or green
        at(SmitsBasis::White) = c.z;
        at(SmitsBasis::Yellow) = std::min(c.x, c.y) - c.z;
        (c.x <= c.y ? at(SmitsBasis::Green) : at(SmitsBasis::Red)) = std::fabs(c.y - c.x);
    }
    return k;
}

double smitsBasis(SmitsBasis basis, double nm) {
    return TabulatedSpectrum{kBases[int(basis)], 10, kSmitsFirstNm, (kSmitsLastNm - kSmitsFirstNm) / 9}(nm);
}

}  // namespace lenslab
