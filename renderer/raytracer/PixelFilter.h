#pragma once
// Pixel reconstruction by filter importance sampling: each sample's offset from the pixel centre
// is drawn with density proportional to |f|, and carries the weight sign(f) * (integral of |f|) /
// (integral of f), so a pixel is the plain mean of weight times radiance over its samples: an
// unbiased estimate of the filtered image even for filters with negative lobes (Mitchell, Lanczos
// sinc), and never needing samples of neighbouring pixels (tiles stay independent). pbrt-v3's
// filters are all separable, so x and y are sampled independently from tabulated profiles.
#include <vector>

#include "PiecewiseConstant.h"
#include "SceneDescription.h"

namespace lenslab {

class PixelFilter {
public:
    explicit PixelFilter(const FilterSpec& spec);
    // Offsets in pixels for a 2D sample in [0,1)^2; returns the sample's weight (mean 1).
    float sample(float u1, float u2, float& dx, float& dy) const;
    double radius() const;  // the largest offset, pixels

    // pbrt-v3's filter value at offset x (pixels) along one axis of half-width `width`.
    static double profile(const FilterSpec& spec, double width, double x);

private:
    // One axis: |f| tabulated on [-width, width] and the sign of f per bin.
    struct Axis {
        double width = 0.5;
        PiecewiseConstant1D absolute;
        std::vector<float> signedWeight;  // sign(f) * integral |f| / integral f, per bin
        float sample(float u, float& weight) const;
    };
    static Axis makeAxis(const FilterSpec& spec, double width);
    Axis x_, y_;
};

}  // namespace lenslab
