#pragma once
// Splits the rendered pixel rectangle into square tiles, in row-major order.
#include <vector>

namespace lenslab {

struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
};

std::vector<PixelRect> makeTiles(const PixelRect& area, int tileSize);

}  // namespace lenslab
