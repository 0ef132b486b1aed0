#include "PixelFilter.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {
constexpr int kBins = 256;
}

PixelFilter::Profile PixelFilter::makeProfile(const FilterSpec& spec, double width) {
    Profile p;
    p.width = width;
    if (spec.type == FilterType::Box) return p;
    // pbrt's Gaussian: exp(-alpha x^2) - exp(-alpha w^2), zero at the edge.
    const double edge = std::exp(-spec.alpha * width * width);
    p.cdf.assign(kBins + 1, 0.0f);
    double sum = 0;
    std::vector<double> acc(kBins + 1, 0.0);
    for (int i = 0; i < kBins; ++i) {
        const double x = -width + (i + 0.5) * 2.0 * width / kBins;
        sum += std::max(0.0, std::exp(-spec.alpha * x * x) - edge);
        acc[i + 1] = sum;
    }
    for (int i = 0; i <= kBins; ++i) p.cdf[i] = float(acc[i] / sum);
    return p;
}

float PixelFilter::Profile::invert(float u) const {
    if (cdf.empty()) return float((2.0 * u - 1.0) * width);
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    const int i = std::clamp(int(it - cdf.begin()) - 1, 0, kBins - 1);
    const float span = cdf[i + 1] - cdf[i];
    const float f = span > 0 ? (u - cdf[i]) / span : 0.5f;
    return float(-width + (i + f) * 2.0 * width / kBins);
}

PixelFilter::PixelFilter(const FilterSpec& spec) : x_(makeProfile(spec, spec.xwidth)), y_(makeProfile(spec, spec.ywidth)) {}

void PixelFilter::sample(float u1, float u2, float& dx, float& dy) const {
    dx = x_.invert(u1);
    dy = y_.invert(u2);
}

double PixelFilter::radius() const { return std::max(x_.width, y_.width); }

}  // namespace lenslab
