#pragma once
// Colour as the lens designer first checks it: the first-order data at the F, d and C lines, the
// longitudinal colour (where red and blue focus on the axis) and the lateral colour (how far apart
// red and blue images of an off-axis point land).
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"

namespace lenslab {

struct Chromatic {
    double eflF = 0, eflD = 0, eflC = 0;           // mm
    // Paraxial image of the plane of focus (F' for an object at infinity), mm, lens convention.
    double imageZF = 0, imageZD = 0, imageZC = 0;
    double longitudinalColour = 0;  // imageZC - imageZF, mm (positive: red focuses in front of blue, toward the scene)
    // Chief-ray heights of F minus C on the d image plane, at the largest field the lens passes a
    // chief ray (at d) through every clear aperture, mm.
    double lateralColour = 0;
    double lateralColourFieldDegrees = 0;
    double lateralColourImageHeight = 0;  // the d chief ray's height there, mm
};

// For a lens without dispersion the three lines coincide, the colours are 0 and no field is searched.
// `objectZ` is the plane of focus (lens convention; +infinity for an object at infinity). Throws
// OpticsError when a near-axis ray cannot pass at one of the three wavelengths.
Chromatic computeChromatic(const LensSystem& lens, double objectZ);

// The paraxial image of the axial point at objectZ (lens convention; +infinity: F'), mm.
double paraxialImageZ(const LensSystem& lens, const FirstOrder& fo, double objectZ);

// The largest field angle (degrees, below 85) whose chief ray at the lens's wavelength passes every
// clear aperture: the lens's own field of view as traced.
double largestChiefRayField(const LensSystem& lens);

}  // namespace lenslab
