#pragma once
// pbrt-v4's film white balance: a von Kries adaptation in the Bradford cone space that maps the
// white of a CIE daylight illuminant at the given temperature onto the output's white, D65. A
// scene lit by a 4000 K source and balanced for 4000 K renders its whites neutral.
#include <array>

#include "core/Vec3f.h"

namespace lenslab {

using Rgb3x3 = std::array<float, 9>;  // row-major, linear sRGB to linear sRGB

Rgb3x3 whiteBalanceMatrix(double kelvin);
Vec3f applyRgbMatrix(const Rgb3x3& m, Vec3f c);

}  // namespace lenslab
