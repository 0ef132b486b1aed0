#pragma once
// The diffraction image of a point from its pupil function: the PSF is |FFT(P)|^2 over the
// zero-padded pupil grid, and the OTF along x (sagittal) and y (tangential) the Fourier transform
// of the PSF's line spread along that direction, which equals the autocorrelation of P. The
// aberration-free circular pupil's MTF, (2/pi)(phi - cos phi sin phi) with phi = acos(nu/nu_c) and
// nu_c = 2 NA / lambda = 1 / (lambda N), is given for reference.
#include <vector>

#include "analysis/Fft.h"
#include "analysis/GeometricMtf.h"
#include "analysis/WavefrontMap.h"

namespace lenslab {

struct PointSpreadFunction {
    int size = 0;                   // K: K x K samples, row-major (row index along y)
    double spacingX = 0, spacingY = 0;  // mm per sample on the image plane
    std::vector<double> intensity;  // sums to 1; sample (K/2, K/2) is the chief ray's image point
    // The OTF's scale beyond zero frequency: sum |P|^2 over the pupil's area. Averaging P over an
    // edge cell blurs the pupil's outline by about a cell, which lowers the pupil's autocorrelation
    // at zero shift only (it rounds the MTF's cusp inside the first sample); normalising by the
    // area instead keeps every sampled frequency right.
    double transferScale = 1;
};

// K = the power of two at or above padding x the pupil grid (padding >= 2 samples the PSF at the
// Nyquist rate of its intensity). Throws std::invalid_argument for padding < 2 or K > 4096.
PointSpreadFunction pointSpreadFunction(const WavefrontMap& wavefront, int padding = 2);

// The complex OTF along one direction, sampled every `spacing` lp/mm from 0, relative to the chief
// ray's image point (a PSF off it shows as a phase).
struct TransferFunction {
    double spacing = 0;                // lp/mm per sample
    std::vector<Complex> values;       // values[0] = 1
    Complex at(double frequency) const;  // linear interpolation; 0 beyond the samples
};

struct OpticalTransfer {
    TransferFunction sagittal;    // frequency along x
    TransferFunction tangential;  // frequency along y
};

OpticalTransfer opticalTransfer(const PointSpreadFunction& psf);

// The OTF along one direction at `frequency`, measured from a point `offset` (mm) away from the chief
// ray's image (its offset a phase): how wavelengths' OTFs are summed about one reference point.
Complex shiftedTransfer(const OpticalTransfer& otf, MtfDirection direction, double frequency, Point2 offset);

// The aberration-free MTF of a circular pupil, (2/pi)(phi - cos phi sin phi) with phi = acos(nu /
// cutoff), 0 from the cutoff on; with a central obscuration of `obscuration` times the pupil's radius
// (a reflex lens's secondary mirror), the annular pupil's (O'Neill 1956).
double diffractionLimitedMtf(double frequency, double cutoff, double obscuration = 0);

}  // namespace lenslab
