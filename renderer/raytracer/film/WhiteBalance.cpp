#include "film/WhiteBalance.h"

#include "core/DaylightSpectrum.h"
#include "core/Matrix3.h"

namespace lenslab {

namespace {

// Linear sRGB (D65) and XYZ; the Bradford cone response and its inverse.
constexpr Matrix3 kRgbToXyz = {0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920, 0.9503041};
constexpr Matrix3 kXyzToRgb = {3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434, -0.2040259, 1.0572252};
constexpr Matrix3 kBradford = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};
constexpr Matrix3 kBradfordInverse = {0.9869929, -0.1470543, 0.1599627, 0.4323053, 0.5183603, 0.0492912, -0.0085287, 0.0400428, 0.9684867};

}  // namespace

Rgb3x3 whiteBalanceMatrix(double kelvin) {
    double x, y;
    daylightChromaticity(kelvin, x, y);
    const Triple lmsSource = applyMatrix(kBradford, {x / y, 1, (1 - x - y) / y});
    const Triple lmsTarget = applyMatrix(kBradford, {0.95047, 1, 1.08883});
    const Matrix3 gain = {lmsTarget[0] / lmsSource[0], 0, 0, 0, lmsTarget[1] / lmsSource[1], 0, 0, 0, lmsTarget[2] / lmsSource[2]};
    const Matrix3 m = multiply(kXyzToRgb, multiply(kBradfordInverse, multiply(gain, multiply(kBradford, kRgbToXyz))));
    Rgb3x3 out;
    for (int i = 0; i < 9; ++i) out[i] = float(m[i]);
    return out;
}

Vec3f applyRgbMatrix(const Rgb3x3& m, Vec3f c) {
    return {m[0] * c.x + m[1] * c.y + m[2] * c.z, m[3] * c.x + m[4] * c.y + m[5] * c.z, m[6] * c.x + m[7] * c.y + m[8] * c.z};
}

}  // namespace lenslab
