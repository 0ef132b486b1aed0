#pragma once
// How two renders of the same scene differ, measured on the 8-bit sRGB pictures people look at.
#include "PngCodec.h"

namespace lenslab {

// Root mean square over pixels and the R, G, B channels, in 8-bit levels. PngError when the sizes differ.
double rmsDifference(const RgbaImage& a, const RgbaImage& b);

// Per pixel the largest channel difference times `gain`, shown dark on white (white = identical).
RgbaImage differenceImage(const RgbaImage& a, const RgbaImage& b, double gain);

}  // namespace lenslab
