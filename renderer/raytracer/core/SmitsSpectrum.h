#pragma once
// RGB to spectrum by Smits, "An RGB-to-Spectrum Conversion for Reflectances", Journal of Graphics
// Tools 4(4), 1999: the smallest channel as white, the next as cyan, magenta or yellow, the rest as
// red, green or blue, each a smooth spectrum from the paper's table. It is linear in the RGB
// within each of its six orderings of the channels (so it serves radiance as well as reflectance),
// and equal channels give exactly their multiple of the white spectrum.
#include <array>

#include "core/Vec3f.h"

namespace lenslab {

enum class SmitsBasis { White, Cyan, Magenta, Yellow, Red, Green, Blue };
constexpr int kSmitsBases = 7;

// How much of each basis spectrum makes the RGB's spectrum (all >= 0 for non-negative RGB).
std::array<float, kSmitsBases> smitsCoefficients(const Vec3f& rgb);

// A basis spectrum at a wavelength (nm): the paper's ten values at equal steps from 380 to 720 nm,
// linearly interpolated, the end values held beyond.
double smitsBasis(SmitsBasis basis, double nm);

}  // namespace lenslab
