#pragma once
// Estimates that samples leave in pixels other than their own (render/HeroWavelengths.h), summed
// over the rectangle of pixels they reach, which grows as they arrive. Sums are made in a fixed
// order (a rect's rows one after the other, each in the order its samples made them), so that a
// frame is the same to the bit however its tiles and rows are spread over threads and processes.
#include <vector>

#include "core/Vec3f.h"
#include "render/TileScheduler.h"

namespace lenslab {

class SplatBuffer {
public:
    void add(int x, int y, Vec3f value);
    // Adds `other` pixel by pixel (the merge of a rect's rows, or of a frame's tiles).
    void add(const SplatBuffer& other);
    void clear();
    bool empty() const { return rgb_.empty(); }
    const PixelRect& box() const { return box_; }  // full-image pixels; empty: nothing yet
    const std::vector<float>& rgb() const { return rgb_; }  // box's pixels, row-major, 3 floats each
    // A buffer received whole (an MPI worker's tile).
    static SplatBuffer fromParts(const PixelRect& box, std::vector<float> rgb);

private:
    void reach(const PixelRect& r);  // grows the box to hold r
    PixelRect box_;
    std::vector<float> rgb_;
};

}  // namespace lenslab
