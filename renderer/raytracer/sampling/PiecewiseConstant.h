#pragma once
// Piecewise-constant distributions for importance sampling: a 1D one over n equal bins of [0, 1)
// (pixel filter profiles, choosing a light by power) and a 2D one over an image (environment
// maps), sampled as a marginal over rows times the chosen row's conditional.
#include <cstddef>
#include <vector>

namespace lenslab {

class PiecewiseConstant1D {
public:
    // f >= 0 per bin; all zero (or empty input) samples uniformly.
    explicit PiecewiseConstant1D(std::vector<float> f);
    float integral() const { return integral_; }  // of f over [0, 1)
    // A point in [0, 1) with density f(x) / integral; pdf receives that density, bin the bin.
    float sampleContinuous(float u, float& pdf, std::size_t& bin) const;
    // A bin with probability f[bin] / sum(f); pmf receives it.
    std::size_t sampleDiscrete(float u, float& pmf) const;
    float binProbability(std::size_t bin) const;
    const std::vector<float>& cdf() const { return cdf_; }  // 0, then each bin's end, up to 1
    float density(float x) const;  // pdf of sampleContinuous at x in [0, 1)

private:
    std::size_t findBin(float u) const;
    std::vector<float> f_, cdf_;  // cdf_ has one entry more than f_, 0 to 1
    float integral_ = 0;
};

// An image's (width x height) non-negative values as a density over (s, t) in [0, 1)^2, s across
// the columns and t down the rows.
class PiecewiseConstant2D {
public:
    PiecewiseConstant2D(const std::vector<float>& values, int width, int height);
    // Returns (s, t); pdf receives the density in (s, t).
    void sample(float u1, float u2, float& s, float& t, float& pdf) const;
    float density(float s, float t) const;

private:
    std::vector<PiecewiseConstant1D> rows_;  // conditional over s, per row
    PiecewiseConstant1D marginal_;           // over t: each row's integral
};

}  // namespace lenslab
