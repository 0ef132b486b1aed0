#pragma once
// The spatial frequency response of a picture measured from a slanted edge in it, by the e-SFR
// method of ISO 12233: the edge's line fitted to each row's centroid of the derivative across it,
// every pixel projected along that line onto the edge's normal and binned four to a pixel (the edge
// spread function, oversampled because the slant puts each row's pixels at another phase), its
// central difference (the line spread function) under a Hamming window, the Fourier transform's
// modulus over its value at 0, divided by the central difference's own transfer function.
//
// It measures what the picture holds: the lens's MTF times the pixel's (its aperture and the
// render's filter). Two departures from the standard's letter, both to compare with an analysis:
// distances are measured along the edge's normal (not along the pixel row), so frequencies are
// along the normal; and the transform is evaluated at the frequencies asked for (the sum the FFT
// computes at k / length, taken at any frequency), so no interpolation lies between the two.
// Binning a quarter pixel wide leaves its own factor sin(pi f / 4) / (pi f / 4) in the result, as
// in the standard: 0.994 at half the pixel Nyquist, 0.974 at Nyquist.
#include <vector>

namespace lenslab {

// A region of a picture: linear values, row-major, top row first.
struct PixelRegion {
    int width = 0, height = 0;
    std::vector<double> values;
};

struct EdgeSfr {
    bool alongRows = true;        // the edge crosses the rows (it runs near the columns): values vary along x
    double angleDegrees = 0;      // the edge's slant from the pixel column (alongRows) or row, signed
    double normalX = 1, normalY = 0;  // unit normal of the edge in pixel axes (x right, y down)
    double centreX = 0, centreY = 0;  // the fitted edge's point at the region's middle, pixels from its top-left corner
    int rowsUsed = 0;             // rows (columns) across the edge that entered: whole turns of the slant's phase
    std::vector<double> frequencies;  // cycles per pixel along the normal, as asked
    std::vector<double> sfr;          // at each frequency
};

// Throws std::invalid_argument naming the problem when the region holds no usable edge: too small,
// a value not finite, no step across a row, a slant under 1 degree (too few phases for four bins a
// pixel) or over 30 degrees, or too few rows for one whole turn of the phase.
EdgeSfr slantedEdgeSfr(const PixelRegion& region, const std::vector<double>& cyclesPerPixel);

}  // namespace lenslab
