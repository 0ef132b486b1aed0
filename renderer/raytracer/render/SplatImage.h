#pragma once
// A frame's splats (render/HeroWavelengths.h: a spectral sample's wavelengths landing in pixels
// other than its own), summed tile by tile in tile order whatever order the tiles finish in: the
// frame stays the same to the bit however its tiles are spread over threads and processes. They
// join the image once every tile is done (PreparedFrame::addSplats); until then an image shows
// each pixel's own samples only.
#include <cstddef>
#include <vector>

#include "render/SplatBuffer.h"

namespace lenslab {

class SplatImage {
public:
    explicit SplatImage(std::size_t tiles);
    // Tile `tile`'s splats (a tile done twice, as MPI re-queues a lost worker's, counts once). Not
    // thread-safe: callers serialise.
    void tileDone(std::size_t tile, SplatBuffer splats);
    // The sum over every tile; all must be done.
    const SplatBuffer& sum() const;

private:
    std::vector<SplatBuffer> waiting_;  // per tile, until every earlier tile's are added
    std::vector<bool> done_;
    std::size_t next_ = 0;              // the first tile whose splats are not yet added
    SplatBuffer sum_;
};

}  // namespace lenslab
