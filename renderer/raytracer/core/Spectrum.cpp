#include "core/Spectrum.h"

#include <algorithm>
#include <cmath>

#include "core/ColourMatching.h"

namespace lenslab {

namespace {

// The spectrum at wavelength l: linear between samples, the end values beyond them.
double interpolate(const std::vector<double>& lambda, const std::vector<double>& v, double l) {
    if (l <= lambda.front()) return v.front();
    if (l >= lambda.back()) return v.back();
    const auto hi = std::upper_bound(lambda.begin(), lambda.end(), l) - lambda.begin();
    const double t = (l - lambda[hi - 1]) / (lambda[hi] - lambda[hi - 1]);
    return (1 - t) * v[hi - 1] + t * v[hi];
}

}  // namespace

Vec3f xyzToRgb(double x, double y, double z) {
    // The sRGB / Rec. 709 primaries with a D65 white (IEC 61966-2-1).
    return {float(3.240479 * x - 1.537150 * y - 0.498535 * z), float(-0.969256 * x + 1.875991 * y + 0.041556 * z),
            float(0.055648 * x - 0.204043 * y + 1.057311 * z)};
}

Vec3f sampledSpectrumToRgb(const std::vector<double>& lambda, const std::vector<double>& v) {
    double x = 0, y = 0, z = 0;
    for (int l = kVisibleFirstNm; l <= kVisibleLastNm; ++l) {
        const double s = interpolate(lambda, v, l);
        x += s * cieX(l);
        y += s * cieY(l);
        z += s * cieZ(l);
    }
    const double n = cieYIntegral();
    return xyzToRgb(x / n, y / n, z / n);
}

double planckRadiance(double kelvin, double nm) {
    constexpr double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
    const double l = nm * 1e-9;
    return 2 * h * c * c / (std::pow(l, 5) * (std::exp(h * c / (l * kb * kelvin)) - 1));
}

Vec3f blackbodyToRgb(double kelvin, double scale) {
    const auto planck = [&](double nm) { return planckRadiance(kelvin, nm); };
    const double peak = planck(2.8977721e-3 / kelvin * 1e9);
    std::vector<double> lambda, v;
    for (int l = kVisibleFirstNm; l <= kVisibleLastNm; ++l) {
        lambda.push_back(l);
        v.push_back(planck(l) / peak);
    }
    return float(scale) * sampledSpectrumToRgb(lambda, v);
}

}  // namespace lenslab
