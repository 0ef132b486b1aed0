#pragma once
// A spectrum tabulated at equal wavelength steps: linearly interpolated between its values, the end
// values held beyond them (how Smits's basis spectra and pbrt-v4's measured curves are extended).
#include <algorithm>

namespace lenslab {

struct TabulatedSpectrum {
    const double* values;
    int count;  // at least 2
    double firstNm, stepNm;

    double operator()(double nm) const {
        const double t = std::clamp((nm - firstNm) / stepNm, 0.0, double(count - 1));
        const int i = std::min(int(t), count - 2);
        const double f = t - i;
        return (1 - f) * values[i] + f * values[i + 1];
    }
};

}  // namespace lenslab
