#pragma once
// Pixel reconstruction by filter importance sampling: each sample's offset from the pixel centre
// is drawn with density proportional to |f| and carries the weight sign(f) * (integral of |f|) /
// (integral of f), whose mean is 1; the mean of weight times radiance is then an unbiased estimate
// of the filtered image even for filters with negative lobes (Mitchell, Lanczos sinc), and a pixel
// never needs samples of its neighbours (tiles stay independent). pbrt-v3's filters are all
// separable, so x and y are sampled independently from tabulated profiles.
#include <vector>

#include "sampling/PiecewiseConstant.h"
#include "scene/SceneDescription.h"
#include "core/Vec3f.h"

namespace lenslab {

class PixelFilter {
public:
    explicit PixelFilter(const FilterSpec& spec);
    // Offsets in pixels for a 2D sample in [0,1)^2; returns the sample's weight (mean 1).
    float sample(float u1, float u2, float& dx, float& dy) const;
    // The density of sample()'s offset along x (dx, per pixel; 0 beyond the filter) and the factor
    // of the weight sample() gives there; the same along y. The 2D density is their product.
    float densityX(double dx, float& weight) const { return x_.density(dx, weight); }
    float densityY(double dy, float& weight) const { return y_.density(dy, weight); }
    double radiusX() const { return x_.width; }
    double radiusY() const { return y_.width; }
    double radius() const;  // the largest offset, pixels

    // pbrt-v3's filter value at offset x (pixels) along one axis of half-width `width`.
    static double profile(const FilterSpec& spec, double width, double x);

private:
    // One axis: |f| tabulated on [-width, width] and the sign of f per bin.
    struct Axis {
        double width = 0.5;
        bool uniform = false;  // box: no table to search, every weight 1
        PiecewiseConstant1D absolute;
        std::vector<float> signedWeight;  // sign(f) * integral |f| / integral f, per bin
        float sample(float u, float& weight) const;
        float density(double x, float& weight) const;
    };
    static Axis makeAxis(const FilterSpec& spec, double width);
    Axis x_, y_;
};

// A pixel's value from its samples (filter weight, camera-weighted radiance). The plain mean of
// weight x value is unbiased, but where the image is flat its noise is that of the weights' own
// mean (for Mitchell at 16 samples, 10% of the value). Adding (1 - mean weight) x (mean value), a
// control variate as the weights' mean is 1 in expectation, makes a flat region exact and leaves a
// bias of (mean under |f| - filtered value) / n at edges, vanishing as samples grow; unlike the
// ratio sum(w v) / sum(w) it never divides by a sum that positive and negative weights can cancel.
// With positive filters every weight is exactly 1 and this is the plain mean.
class FilteredPixel {
public:
    void add(float weight, Vec3f value) {
        weighted_ += weight * value;
        plain_ += value;
        weights_ += weight;
        ++count_;
    }
    Vec3f value() const {
        if (count_ == 0) return {};
        const float n = float(count_);
        return weighted_ / n + (1.0f - weights_ / n) * (plain_ / n);
    }

private:
    Vec3f weighted_, plain_;
    float weights_ = 0;
    int count_ = 0;
};

}  // namespace lenslab
