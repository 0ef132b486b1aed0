#include "analysis/DiffractionMtf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

// The transform of a line spread sampled every `spacing` mm with x = 0 at index 0 (negative x
// wrapped to the end): OTF(nu) = sum LSF(x) exp(-2 pi i nu x), kept up to half the samples.
TransferFunction transferOf(std::vector<Complex> lineSpread, double spacing, double scale) {
    const std::size_t k = lineSpread.size();
    fft(lineSpread, -1);
    TransferFunction t;
    t.spacing = 1.0 / (k * spacing);
    const Complex total = lineSpread[0];
    t.values.push_back(1.0);
    for (std::size_t i = 1; i <= k / 2; ++i) t.values.push_back(scale * lineSpread[i] / total);
    return t;
}

}  // namespace

PointSpreadFunction pointSpreadFunction(const WavefrontMap& w, int padding) {
    if (padding < 2) throw std::invalid_argument("point spread function: the padding must be at least 2");
    const std::size_t n = w.samples, k = nextPowerOfTwo(static_cast<std::size_t>(padding) * n);
    if (k > 4096) throw std::invalid_argument("point spread function: at most 4096 x 4096 samples");
    std::vector<Complex> field(k * k, Complex(0, 0));
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) field[j * k + i] = w.pupilFunction[j * n + i];
    // U(x) = sum P(L) exp(+2 pi i L.x / lambda) over the grid of direction cosines L.
    fft2d(field, k, +1);
    PointSpreadFunction psf;
    psf.size = static_cast<int>(k);
    const double lambda = w.wavelength * 1e-6;
    psf.spacingX = lambda * n / (k * 2 * std::fabs(w.aperture.x));
    psf.spacingY = lambda * n / (k * 2 * std::fabs(w.aperture.y));
    psf.intensity.resize(k * k);
    double total = 0;
    for (std::size_t j = 0; j < k; ++j)
        for (std::size_t i = 0; i < k; ++i) {
            // Index 0 is x = 0: shift it to the grid's centre.
            const double v = std::norm(field[j * k + i]);
            psf.intensity[((j + k / 2) % k) * k + (i + k / 2) % k] = v;
            total += v;
        }
    if (total > 0)
        for (double& v : psf.intensity) v /= total;
    double energy = 0;  // sum |P|^2
    for (const Complex& p : w.pupilFunction) energy += std::norm(p);
    if (w.passingCells > 0) psf.transferScale = energy / w.passingCells;
    return psf;
}

OpticalTransfer opticalTransfer(const PointSpreadFunction& psf) {
    const std::size_t k = psf.size;
    std::vector<Complex> alongX(k, Complex(0, 0)), alongY(k, Complex(0, 0));
    for (std::size_t j = 0; j < k; ++j)
        for (std::size_t i = 0; i < k; ++i) {
            const double v = psf.intensity[j * k + i];
            // Back from centred to x = 0 at index 0.
            alongX[(i + k / 2) % k] += v;
            alongY[(j + k / 2) % k] += v;
        }
    return {transferOf(std::move(alongX), psf.spacingX, psf.transferScale),
            transferOf(std::move(alongY), psf.spacingY, psf.transferScale)};
}

Complex TransferFunction::at(double frequency) const {
    const double index = frequency / spacing;
    if (!(index >= 0) || index >= double(values.size() - 1)) return 0;
    const std::size_t i = static_cast<std::size_t>(index);
    const double t = index - double(i);
    return (1 - t) * values[i] + t * values[i + 1];
}

double diffractionLimitedMtf(double frequency, double cutoff, double obscuration) {
    const double v = frequency / cutoff, e = obscuration;
    if (!(v < 1)) return 0;
    auto lens = [](double s) { return std::acos(s) - s * std::sqrt(1 - s * s); };  // 2 circles' overlap, pi/2 at 0
    const double a = 2 / kPi * lens(std::max(0.0, v));
    if (!(e > 0)) return a;
    // O'Neill 1956: the annulus's autocorrelation, the outer circle's (a) and the inner's (b) less
    // twice the overlap of outer and inner (c), over the annulus's area 1 - e^2.
    const double b = v < e ? 2 * e * e / kPi * lens(v / e) : 0.0;
    double c = 0;
    if (v <= (1 - e) / 2) {
        c = -2 * e * e;
    } else if (v < (1 + e) / 2) {
        const double phi = std::acos(std::clamp((1 + e * e - 4 * v * v) / (2 * e), -1.0, 1.0));
        c = 2 * e / kPi * std::sin(phi) + (1 + e * e) / kPi * phi -
            2 * (1 - e * e) / kPi * std::atan((1 + e) / (1 - e) * std::tan(phi / 2)) - 2 * e * e;
    }
    return std::max(0.0, (a + b + c) / (1 - e * e));
}

Complex shiftedTransfer(const OpticalTransfer& otf, MtfDirection direction, double frequency, Point2 offset) {
    constexpr double kTwoPi = 6.28318530717958647692;
    return direction == MtfDirection::Sagittal ? otf.sagittal.at(frequency) * std::polar(1.0, -kTwoPi * frequency * offset.x)
                                               : otf.tangential.at(frequency) * std::polar(1.0, -kTwoPi * frequency * offset.y);
}

}  // namespace lenslab
