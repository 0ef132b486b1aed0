#pragma once
// A colour mosaic's raw numbers as a DNG file (Adobe's Digital Negative 1.4, a TIFF written by
// libtiff) that raw developers open: one 16-bit CFA plane, its Bayer pattern, black and white
// levels, and the camera's colour: its channels are linear Rec. 709 (ColorMatrix1 the XYZ to
// Rec. 709 matrix under D65) and already white-balanced (AsShotNeutral 1 1 1).
#include <cstdint>
#include <vector>

#include "film/BayerMosaic.h"

namespace lenslab {

std::vector<std::uint8_t> encodeDng(const RawMosaic& raw);

}  // namespace lenslab
