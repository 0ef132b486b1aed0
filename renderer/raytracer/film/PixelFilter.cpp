#include "film/PixelFilter.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

constexpr int kTableBins = 512;

double sinc(double x) {
    const double px = M_PI * x;
    return std::fabs(x) < 1e-5 ? 1.0 - px * px / 6.0 : std::sin(px) / px;
}

// Mitchell and Netravali's cubic on |x| in [0, 2].
double mitchell(double x, double B, double C) {
    x = std::fabs(x);
    if (x >= 2) return 0;
    if (x > 1)
        return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6;
    return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6;
}

}  // namespace

double PixelFilter::profile(const FilterSpec& spec, double width, double x) {
    if (std::fabs(x) > width) return 0;
    switch (spec.type) {
        case FilterType::Box:
            return 1;
        case FilterType::Gaussian:  // zero at the edge
            return std::max(0.0, std::exp(-spec.alpha * x * x) - std::exp(-spec.alpha * width * width));
        case FilterType::Triangle:
            return width - std::fabs(x);
        case FilterType::Mitchell:  // the cubic's support [-2, 2] stretched over [-width, width]
            return mitchell(2 * x / width, spec.B, spec.C);
        case FilterType::Sinc:  // Lanczos: sinc windowed by a sinc tau times wider
            return sinc(x) * sinc(x / spec.tau);
    }
    return 0;
}

PixelFilter::Axis PixelFilter::makeAxis(const FilterSpec& spec, double width) {
    // Each bin's value is the mean of the profile over it (Simpson's rule): the negative lobes are
    // narrow enough that the bin midpoint alone would misplace their share.
    std::vector<float> absolute(kTableBins), sign(kTableBins);
    double signedSum = 0, absSum = 0;
    const double h = 2 * width / kTableBins;
    for (int i = 0; i < kTableBins; ++i) {
        const double a = -width + i * h;
        const double mean = (profile(spec, width, a) + 4 * profile(spec, width, a + h / 2) +
                             profile(spec, width, a + h)) / 6;
        absolute[i] = float(std::fabs(mean));
        sign[i] = mean < 0 ? -1.0f : 1.0f;
        signedSum += mean;
        absSum += std::fabs(mean);
    }
    Axis axis{width, spec.type == FilterType::Box, PiecewiseConstant1D(std::move(absolute)), {}};
    const float norm = signedSum > 0 ? float(absSum / signedSum) : 1.0f;
    axis.signedWeight.resize(kTableBins);
    for (int i = 0; i < kTableBins; ++i) axis.signedWeight[i] = sign[i] * norm;
    return axis;
}

float PixelFilter::Axis::sample(float u, float& weight) const {
    if (uniform) {
        weight = 1;
        return float((2.0 * u - 1.0) * width);
    }
    float pdf;
    std::size_t bin;
    const float x = absolute.sampleContinuous(u, pdf, bin);
    weight = signedWeight[bin];
    return float((2.0 * x - 1.0) * width);
}

float PixelFilter::Axis::density(double x, float& weight) const {
    weight = 0;
    if (!(std::fabs(x) < width)) return 0;
    if (uniform) {
        weight = 1;
        return float(0.5 / width);
    }
    const float t = float(0.5 * (x / width + 1));  // sample()'s position in [0, 1)
    weight = signedWeight[std::size_t(std::clamp(int(t * float(signedWeight.size())), 0, int(signedWeight.size()) - 1))];
    return absolute.density(t) * float(0.5 / width);
}

PixelFilter::PixelFilter(const FilterSpec& spec) : x_(makeAxis(spec, spec.xwidth)), y_(makeAxis(spec, spec.ywidth)) {}

float PixelFilter::sample(float u1, float u2, float& dx, float& dy) const {
    float wx, wy;
    dx = x_.sample(u1, wx);
    dy = y_.sample(u2, wy);
    return wx * wy;
}

double PixelFilter::radius() const { return std::max(x_.width, y_.width); }

}  // namespace lenslab
