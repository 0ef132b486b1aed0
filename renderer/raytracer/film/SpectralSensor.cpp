#include "film/SpectralSensor.h"

#include "core/ColourMatching.h"
#include "core/Spectrum.h"

namespace lenslab {

namespace {

constexpr int kBands = kVisibleLastNm - kVisibleFirstNm + 1;

std::vector<float> matchingSum() {
    std::vector<float> f(kBands);
    for (int b = 0; b < kBands; ++b) {
        const double nm = kVisibleFirstNm + b;
        f[b] = float(cieX(nm) + cieY(nm) + cieZ(nm));
    }
    return f;
}

Vec3f bandRgb(int band, double spectrumValue) {
    const double nm = kVisibleFirstNm + band, n = cieYIntegral();
    return xyzToRgb(spectrumValue * cieX(nm) / n, spectrumValue * cieY(nm) / n, spectrumValue * cieZ(nm) / n);
}

}  // namespace

SpectralSensor::SpectralSensor() : bands_(matchingSum()), response_(kBands) {
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
}

WavelengthSample SpectralSensor::sample(float u) const {
    float pdf;
    std::size_t bin;
    bands_.sampleContinuous(u, pdf, bin);
    WavelengthSample w;
    w.band = int(bin);
    w.nm = kVisibleFirstNm + w.band;
    w.probability = bands_.binProbability(bin);
    return w;
}

Vec3f SpectralSensor::toRgb(const Vec3f& radiance, const WavelengthSample& w) const {
    const std::array<float, kSmitsBases> c = smitsCoefficients(radiance);
    const std::array<Vec3f, kSmitsBases>& r = response_[w.band];
    Vec3f sum{0, 0, 0};
    for (int k = 0; k < kSmitsBases; ++k) sum = sum + c[k] * r[k];
    return (1.0f / w.probability) * sum;
}

}  // namespace lenslab
