#include "film/WhiteBalance.h"

namespace lenslab {

namespace {

using M3 = std::array<double, 9>;

M3 multiply(const M3& a, const M3& b) {
    M3 c{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) c[r * 3 + j] += a[r * 3 + k] * b[k * 3 + j];
    return c;
}

void apply(const M3& m, const double in[3], double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = m[r * 3] * in[0] + m[r * 3 + 1] * in[1] + m[r * 3 + 2] * in[2];
}

// Linear sRGB (D65) and XYZ; the Bradford cone response and its inverse.
constexpr M3 kRgbToXyz = {0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920, 0.9503041};
constexpr M3 kXyzToRgb = {3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434, -0.2040259, 1.0572252};
constexpr M3 kBradford = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};
constexpr M3 kBradfordInverse = {0.9869929, -0.1470543, 0.1599627, 0.4323053, 0.5183603, 0.0492912, -0.0085287, 0.0400428, 0.9684867};

}  // namespace

void daylightChromaticity(double kelvin, double& x, double& y) {
    const double t = kelvin, t2 = t * t, t3 = t2 * t;
    x = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                  : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    y = -3 * x * x + 2.87 * x - 0.275;
}

Rgb3x3 whiteBalanceMatrix(double kelvin) {
    double x, y;
    daylightChromaticity(kelvin, x, y);
    const double source[3] = {x / y, 1, (1 - x - y) / y};
    const double d65[3] = {0.95047, 1, 1.08883};
    double lmsSource[3], lmsTarget[3];
    apply(kBradford, source, lmsSource);
    apply(kBradford, d65, lmsTarget);
    const M3 gain = {lmsTarget[0] / lmsSource[0], 0, 0, 0, lmsTarget[1] / lmsSource[1], 0, 0, 0, lmsTarget[2] / lmsSource[2]};
    const M3 m = multiply(kXyzToRgb, multiply(kBradfordInverse, multiply(gain, multiply(kBradford, kRgbToXyz))));
    Rgb3x3 out;
    for (int i = 0; i < 9; ++i) out[i] = float(m[i]);
    return out;
}

Vec3f applyRgbMatrix(const Rgb3x3& m, Vec3f c) {
    return {m[0] * c.x + m[1] * c.y + m[2] * c.z, m[3] * c.x + m[4] * c.y + m[5] * c.z, m[6] * c.x + m[7] * c.y + m[8] * c.z};
}

}  // namespace lenslab
