#pragma once
// The 24 swatches of the ColorChecker chart as measured reflectance spectra: the training set
// against which pbrt-v4 fits a camera sensor's colour matrix (film/CameraSensor.h).
#include "core/TabulatedSpectrum.h"

namespace lenslab {

constexpr int kColourCheckerSwatches = 24;

// Swatch i (0: dark skin ... 23: black), 380 to 730 nm, the end values held beyond.
TabulatedSpectrum colourCheckerSwatch(int i);

}  // namespace lenslab
