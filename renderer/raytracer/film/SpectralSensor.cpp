#include "film/SpectralSensor.h"

#include <cmath>

#include "core/ColourMatching.h"
#include "core/Spectrum.h"

namespace lenslab {

namespace {

constexpr int kBands = kVisibleLastNm - kVisibleFirstNm + 1;

Vec3f bandRgb(int band, double spectrumValue) {
    const double nm = kVisibleFirstNm + band, n = cieYIntegral();
    return xyzToRgb(spectrumValue * cieX(nm) / n, spectrumValue * cieY(nm) / n, spectrumValue * cieZ(nm) / n);
}

}  // namespace

SpectralSensor::SpectralSensor() : bands_(std::vector<float>{}), response_(kBands) {
    // Each basis's own colour: white, cyan, magenta, yellow, red, green, blue.
    static const Vec3f kNominal[kSmitsBases] = {{1, 1, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < kSmitsBases; ++k) {
        std::vector<Vec3f> perBand(kBands);
        double total[3] = {0, 0, 0};
        for (int b = 0; b < kBands; ++b) {
            perBand[b] = bandRgb(b, smitsBasis(SmitsBasis(k), kVisibleFirstNm + b));
            for (int c = 0; c < 3; ++c) total[c] += perBand[b][c];
        }
        // Calibrated so that the basis comes back exactly as its colour (a channel it should not
        // have, dropped): the published spectra return a few percent off through these matching
        // functions and primaries (red at 0.90, cyan with 0.10 of red).
        for (int b = 0; b < kBands; ++b)
            response_[b][k] = {float(perBand[b].x * kNominal[k].x / total[0]), float(perBand[b].y * kNominal[k].y / total[1]),
                               float(perBand[b].z * kNominal[k].z / total[2])};
    }
    // Wavelengths drawn in proportion to the film's summed response to white, channel by channel
    // absolute (each channel's share then never exceeds 1 / its probability).
    std::vector<float> f(kBands);
    for (int b = 0; b < kBands; ++b)
        f[b] = std::fabs(response_[b][0].x) + std::fabs(response_[b][0].y) + std::fabs(response_[b][0].z);
    bands_ = PiecewiseConstant1D(std::move(f));
    const std::vector<float>& cdf = bands_.cdf();
    for (int j = 0; j < kGuide; ++j) {
        std::uint16_t b = 0;
        while (b + 1 < kBands && cdf[b + 1] <= float(j) / kGuide) ++b;
        guide_.push_back(b);
    }
}

WavelengthSample SpectralSensor::sample(float u) const {
    // sampleContinuous's band, found from the guide: the first band whose end lies above u.
    const std::vector<float>& cdf = bands_.cdf();
    std::size_t bin = guide_[std::min(int(u * kGuide), kGuide - 1)];
    while (bin + 2 < cdf.size() && cdf[bin + 1] <= u) ++bin;
    WavelengthSample w;
    w.band = int(bin);
    w.nm = kVisibleFirstNm + w.band;
    w.probability = bands_.binProbability(bin);
    return w;
}

void SpectralSensor::sample(float u, int n, WavelengthSample* out) const {
    for (int k = 0; k < n; ++k) {
        const float v = u + float(k) / float(n);
        out[k] = sample(v < 1.0f ? v : v - 1.0f);
    }
}

Vec3f SpectralSensor::toRgb(const Vec3f& radiance, const WavelengthSample& w) const {
    return toRgb(smitsCoefficients(radiance), w);
}

Vec3f SpectralSensor::toRgb(const std::array<float, kSmitsBases>& c, const WavelengthSample& w) const {
    const std::array<Vec3f, kSmitsBases>& r = response_[w.band];
    Vec3f sum{0, 0, 0};
    for (int k = 0; k < kSmitsBases; ++k) sum = sum + c[k] * r[k];
    return (1.0f / w.probability) * sum;
}

}  // namespace lenslab
