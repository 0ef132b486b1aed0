#pragma once
// The film of a spectral render: each camera sample carries wavelengths (render/HeroWavelengths.h);
// the RGB radiance its ray brings back becomes spectral radiance at each (Smits 1999,
// core/SmitsSpectrum.h) and is scored through the CIE 1931 colour matching functions
// (core/ColourMatching.h), divided by the wavelength's probability, into linear Rec. 709 (sRGB
// primaries), as the RGB film stores.
//
// Wavelengths are drawn in 1 nm bands from 360 to 830 nm (the bands the lens's indices are
// tabulated in, optics/trace/WavelengthEtas.h) with probability proportional to the sum of the
// absolute values of the film's three responses to white, so that every band the film sees is
// sampled, none it does not, and no channel's estimate from one wavelength exceeds its share's
// inverse (x + y + z of the matching functions left the red channel's violet lobe and the blue's
// tails four times noisier at three wavelengths a sample: bench/README.md). The estimate's
// expectation is the 1 nm sum of the spectrum against the matching functions,
// calibrated per basis spectrum so that each comes back as its own colour (Smits's white exactly
// RGB (1, 1, 1)): RGB -> spectrum -> RGB is the identity, a grey stays grey and a dispersion-free
// lens gives the RGB film's picture; only the lens's dispersion changes colours.
#include <array>
#include <cstdint>
#include <vector>

#include "core/SmitsSpectrum.h"
#include "core/Vec3f.h"
#include "sampling/PiecewiseConstant.h"

namespace lenslab {

struct WavelengthSample {
    double nm = 0;        // the band's centre
    int band = 0;         // 0 at 360 nm
    float probability = 0;
};

class SpectralSensor {
public:
    SpectralSensor();
    WavelengthSample sample(float u) const;
    // n wavelengths stratified over the distribution: the first from u, the others at u + k / n
    // (mod 1). Each alone is distributed as sample(u); the set is the same whichever is first (the
    // symmetry that hero-wavelength MIS needs).
    void sample(float u, int n, WavelengthSample* out) const;
    // The film's linear Rec. 709 estimate from RGB radiance seen at the sampled wavelength.
    Vec3f toRgb(const Vec3f& radiance, const WavelengthSample& w) const;
    // The same from the radiance's Smits coefficients (smitsCoefficients), for several wavelengths
    // of one radiance.
    Vec3f toRgb(const std::array<float, kSmitsBases>& coefficients, const WavelengthSample& w) const;

private:
    PiecewiseConstant1D bands_;
    // Where to start looking for u's band in bands_: the band of each 1 / kGuide of [0, 1) (a
    // sample takes several wavelengths, each one search).
    static constexpr int kGuide = 1024;
    std::vector<std::uint16_t> guide_;
    // Per band and basis: the calibrated Rec. 709 response to that basis spectrum.
    std::vector<std::array<Vec3f, kSmitsBases>> response_;
};

}  // namespace lenslab
