#pragma once
// Camera samples around one field position of the study's film: raster points jittered over the
// pixel there, lens samples uniform, from a fixed seed.
#include <vector>

#include "cameras/Camera.h"
#include "TradeoffCases.h"

namespace lenslab::tradeoff {

// The raster position (full-frame pixels of width x height) of the film point at `field` of the
// way along the film's diagonal from the centre (the top-right corner when field = 1).
void fieldRasterPosition(double field, int width, int height, double& rasterX, double& rasterY);

std::vector<CameraSample> fieldSamples(double field, int width, int height, int count);

}  // namespace lenslab::tradeoff
