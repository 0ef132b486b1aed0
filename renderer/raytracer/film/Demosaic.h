#pragma once
// A Bayer mosaic's one value a site made into a pixel's three, by Malvar, He & Cutler's linear
// interpolation ("High-quality linear interpolation for demosaicing of Bayer-patterned color
// images", ICASSP 2004): a missing channel is its neighbours' bilinear mean, corrected by the
// Laplacian of the site's own channel (weights 1/2, 5/8 and 3/4), which removes most of bilinear
// interpolation's colour fringes at edges while reproducing flat and linearly graded colour exactly.
// The mosaic is mirrored at the image's edges (which keeps the pattern's phase).
#include <vector>

#include "film/BayerMosaic.h"
#include "Render.h"

namespace lenslab {

// sites: width x height values, row-major; pattern: the one at site (0, 0). Needs 2 x 2 sites at
// least (std::invalid_argument otherwise).
Image demosaic(const std::vector<float>& sites, int width, int height, const BayerPattern& pattern);

}  // namespace lenslab
