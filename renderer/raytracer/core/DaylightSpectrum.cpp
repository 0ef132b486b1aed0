#include "core/DaylightSpectrum.h"

#include "core/TabulatedSpectrum.h"

namespace lenslab {

namespace {

// S0, S1, S2 from 300 to 830 nm in 10 nm steps (CIE 15:2004, table T.2; pbrt-v4 tabulates the same
// values with their 5 nm means between, src/pbrt/util/spectrum.cpp at commit 5f7a6068).
constexpr int kDaylightSamples = 54;
constexpr double kComponents[3][kDaylightSamples] = {
    {0.04, 6, 29.6, 55.3, 57.3, 61.8, 61.5, 68.8, 63.4, 65.8, 94.8, 104.8, 105.9, 96.8,
     113.9, 125.6, 125.5, 121.3, 121.3, 113.5, 113.1, 110.8, 106.5, 108.8, 105.3, 104.4, 100, 96,
     95.1, 89.1, 90.5, 90.3, 88.4, 84, 85.1, 81.9, 82.6, 84.9, 81.3, 71.9, 74.3, 76.4,
     63.3, 71.7, 77, 65.2, 47.7, 68.6, 65, 66, 61, 53.3, 58.9, 61.9},
    {0.02, 4.5, 22.4, 42, 40.6, 41.6, 38, 42.4, 38.5, 35, 43.4, 46.3, 43.9, 37.1,
     36.7, 35.9, 32.6, 27.9, 24.3, 20.1, 16.2, 13.2, 8.6, 6.1, 4.2, 1.9, 0, -1.6,
     -3.5, -3.5, -5.8, -7.2, -8.6, -9.5, -10.9, -10.7, -12, -14, -13.6, -12, -13.3, -12.9,
     -10.6, -11.6, -12.2, -10.2, -7.8, -11.2, -10.4, -10.6, -9.7, -8.3, -9.3, -9.8},
    {0, 2, 4, 8.5, 7.8, 6.7, 5.3, 6.1, 3, 1.2, -1.1, -0.5, -0.7, -1.2,
     -2.6, -2.9, -2.8, -2.6, -2.6, -1.8, -1.5, -1.3, -1.2, -1, -0.5, -0.3, 0, 0.2,
     0.5, 2.1, 3.2, 4.1, 4.7, 5.1, 6.7, 7.3, 8.6, 9.8, 10.2, 8.3, 9.6, 8.5,
     7, 7.6, 8, 6.7, 5.2, 7.4, 6.8, 7, 6.4, 5.5, 6.1, 6.5},};

}  // namespace

void daylightChromaticity(double kelvin, double& x, double& y) {
    const double t = kelvin, t2 = t * t, t3 = t2 * t;
    x = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                  : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    y = -3 * x * x + 2.87 * x - 0.275;
}

double daylightSpectrum(double kelvin, double nm) {
    double x, y;
    daylightChromaticity(kelvin, x, y);
    const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
    const double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m, m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m;
    const auto s = [&](int i) { return TabulatedSpectrum{kComponents[i], kDaylightSamples, 300, 10}(nm); };
    return s(0) + m1 * s(1) + m2 * s(2);
}

}  // namespace lenslab
