#include "render/TileScheduler.h"

#include <algorithm>

namespace lenslab {

std::vector<PixelRect> makeTiles(const PixelRect& area, int tileSize) {
    std::vector<PixelRect> tiles;
    for (int y = area.y0; y < area.y1; y += tileSize)
        for (int x = area.x0; x < area.x1; x += tileSize)
            tiles.push_back({x, y, std::min(x + tileSize, area.x1), std::min(y + tileSize, area.y1)});
    return tiles;
}

}  // namespace lenslab
