#pragma once
// The wavefront of one field at one wavelength, as the pupil function the diffraction image is
// computed from. The optical path of real rays is taken to a reference sphere centred on the chief
// ray's point on the image plane and passing through the chief ray's crossing of the exit pupil
// plane; its difference W from the chief ray's path gives P = A exp(2 pi i W / lambda). P is sampled
// on a square grid of normalised pupil coordinates, which stand for image-space direction cosines
// through the linear map of imageSpaceAperture (exact for an aplanatic lens, the usual assumption
// of FFT diffraction codes). A is the share of each cell that passes: edge cells (of the stop, of
// vignetting rims, of an obscuration) are supersampled, so the pupil's outline is not staircased.
#include <optional>
#include <vector>

#include "analysis/Fft.h"
#include "prescription/LensSystem.h"
#include "analysis/PupilAiming.h"
#include "analysis/PupilSampling.h"

namespace lenslab {

struct WavefrontOptions {
    int pupilSamples = 32;   // grid cells across the pupil's diameter (2 to 1024)
    int edgeSubsamples = 4;  // per side, in cells at an edge of the passing region (1 to 16)
};

struct WavefrontMap {
    double wavelength = 0;  // nm
    int samples = 0;        // n: an n x n grid, row-major, row index along y; the index rises with the direction cosine
    std::vector<Complex> pupilFunction;
    ImageSpaceAperture aperture;  // the grid's half-widths in direction cosines
    Point2 chiefImage;            // where the chief ray meets the image plane (the sphere's centre), mm
    double rmsWaves = 0;          // RMS of W over the passing cell centres, piston removed, in waves
    double passingCells = 0;      // the passing region's area in cells (edge cells by their share)
};

// `lens` at the map's wavelength; exitPupilZ the paraxial exit pupil's plane. nullopt when the chief
// ray or the pupil's rim rays cannot be traced. Throws std::invalid_argument for options out of range.
std::optional<WavefrontMap> wavefrontMap(const LensSystem& lens, const FieldAim& aim, double imageZ, double exitPupilZ,
                                         const WavefrontOptions& options = {});

}  // namespace lenslab
