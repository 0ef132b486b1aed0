#pragma once
// Field curvature: where the tangential and sagittal images of each field form. Thin fans of rays
// close to the chief ray (at +-delta of the pupil in y, and in x) meet at the tangential and sagittal
// foci: the limit that Coddington's equations give along the real chief ray, found by tracing.
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab {

struct FieldCurvatureSample {
    double fieldDegrees = 0;
    double tangentialZ = 0, sagittalZ = 0;          // the foci, lens z (mm)
    double tangentialShift = 0, sagittalShift = 0;  // minus the image plane's z, mm (positive: toward the lens)
    bool found = false;                              // the field's thin fans could be aimed and traced
};

// `lens` at one wavelength; objectZ the object plane (infinity allowed); imageZ the image plane.
std::vector<FieldCurvatureSample> fieldCurvature(const LensSystem& lens, double objectZ, double imageZ,
                                                 const std::vector<double>& fieldDegrees);

}  // namespace lenslab
