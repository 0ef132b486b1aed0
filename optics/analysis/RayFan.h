#pragma once
// Transverse ray aberration fans of one field at one wavelength: the ray's miss on the image plane
// against its normalised pupil coordinate, along the tangential (y: rays at (0, py)) and sagittal
// (x: rays at (px, 0)) sections of the pupil.
#include <vector>

#include "prescription/LensSystem.h"
#include "analysis/PupilAiming.h"
#include "analysis/PupilSampling.h"

namespace lenslab {

struct RayFan {
    double wavelength = 0;            // nm
    std::vector<double> pupil;        // normalised pupil coordinate, -1 to 1
    std::vector<double> tangential;   // y on the image plane minus the reference's, mm; NaN where blocked
    std::vector<double> sagittal;     // x minus the reference's, mm; NaN where blocked
};

// `lens` at the fan's wavelength; `samples` >= 2 pupil coordinates from -1 to 1.
RayFan rayFan(const LensSystem& lens, const FieldAim& aim, double imageZ, Point2 reference, int samples);

}  // namespace lenslab
