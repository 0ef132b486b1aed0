#pragma once
// Longitudinal chromatic focal shift: where the paraxial image of the axial object point forms at
// each wavelength, against where it forms at the d line.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct FocalShiftSample {
    double wavelength = 0;  // nm
    double imageZ = 0;      // paraxial image of the plane of focus, lens z (mm)
    double shift = 0;       // imageZ - imageZ at the d line, mm (positive: toward the lens)
};

// objectZ: the plane of focus (lens convention; +infinity for an object at infinity). Throws
// OpticsError when a near-axis ray cannot pass at some wavelength.
std::vector<FocalShiftSample> chromaticFocalShift(const LensSystem& lens, double objectZ,
                                                  const std::vector<double>& wavelengths);

}  // namespace lenslab
