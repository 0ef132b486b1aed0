#pragma once
// Colour as the lens designer first checks it: the first-order data at the F, d and C lines, the
// longitudinal colour (where red and blue focus on the axis) and the lateral colour (how far apart
// red and blue images of an off-axis point land).
#include <optional>

#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"

namespace lenslab {

// The chief-ray heights of F minus C on the d image plane at one field.
struct LateralColour {
    double mm = 0;
    double fieldDegrees = 0;
    double imageHeight = 0;  // the d chief ray's height there, mm
};

struct Chromatic {
    double eflF = 0, eflD = 0, eflC = 0;           // mm
    // Paraxial image of the plane of focus (F' for an object at infinity), mm, lens convention.
    double imageZF = 0, imageZD = 0, imageZC = 0;
    double longitudinalColour = 0;  // imageZC - imageZF, mm (positive: red focuses in front of blue, toward the scene)
    // At the lens's largest field (FieldOfView.h); none when the lens defines no field or a chief
    // ray cannot be traced there.
    std::optional<LateralColour> lateral;
};

// For a lens without dispersion the three lines coincide and the colours are 0.
// `objectZ` is the plane of focus (lens convention; +infinity for an object at infinity). Throws
// OpticsError when a near-axis ray cannot pass at one of the three wavelengths.
Chromatic computeChromatic(const LensSystem& lens, double objectZ, std::optional<double> fieldDegrees);

// The paraxial image of the axial point at objectZ (lens convention; +infinity: F'), mm.
double paraxialImageZ(const LensSystem& lens, const FirstOrder& fo, double objectZ);

}  // namespace lenslab
