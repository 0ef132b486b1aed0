#pragma once
// The film of a spectral render: each camera sample carries one wavelength; the RGB radiance its ray
// brings back becomes spectral radiance at that wavelength (Smits 1999, core/SmitsSpectrum.h) and
// is scored through the CIE 1931 colour matching functions (core/ColourMatching.h), divided by the
// wavelength's probability, into linear Rec. 709 (sRGB primaries), as the RGB film stores.
//
// Wavelengths are drawn in 1 nm bands from 360 to 830 nm (the bands the lens's indices are
// tabulated in, optics/trace/WavelengthEtas.h) with probability proportional to x + y + z of the
// matching functions, so that every band the eye sees is sampled and none it does not. The
// estimate's expectation is the 1 nm sum of the spectrum against the matching functions,
// calibrated per basis spectrum so that each comes back as its own colour (Smits's white exactly
// RGB (1, 1, 1)): RGB -> spectrum -> RGB is the identity, a grey stays grey and a dispersion-free
// lens gives the RGB film's picture; only the lens's dispersion changes colours.
#include <array>
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
    // The film's linear Rec. 709 estimate from RGB radiance seen at the sampled wavelength.
    Vec3f toRgb(const Vec3f& radiance, const WavelengthSample& w) const;

private:
    PiecewiseConstant1D bands_;
    // Per band and basis: the calibrated Rec. 709 response to that basis spectrum.
    std::vector<std::array<Vec3f, kSmitsBases>> response_;
};

}  // namespace lenslab
