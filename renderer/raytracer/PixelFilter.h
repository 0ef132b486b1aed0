#pragma once
// Pixel reconstruction by filter importance sampling: each sample's offset from the pixel centre
// is drawn with density proportional to the filter, so a pixel is the plain mean of its samples
// and never needs samples of its neighbours (tiles stay independent).
#include <vector>

#include "SceneDescription.h"

namespace lenslab {

class PixelFilter {
public:
    explicit PixelFilter(const FilterSpec& spec);
    // Offsets in pixels for a 2D sample in [0,1)^2.
    void sample(float u1, float u2, float& dx, float& dy) const;
    double radius() const;  // the largest offset, pixels

private:
    // Inverse CDF of the 1D filter profile on [-width, width], tabulated.
    struct Profile {
        double width = 0.5;
        std::vector<float> cdf;  // empty: uniform (box)
        float invert(float u) const;
    };
    static Profile makeProfile(const FilterSpec& spec, double width);
    Profile x_, y_;
};

}  // namespace lenslab
