#pragma once
// Clear apertures for the surfaces a file gives none (a Code V file without CIR): the paraxial beam
// of the file's own aperture (EPD, FNO or NAO) and its largest field, traced along the unfolded axis.
#include "prescription/LensSystem.h"

namespace lenslab {

// Sets apertureRadius of every surface with automaticAperture: the stop's to the marginal ray's
// height (so the entrance pupil is the file's), the others to 1.1 times the marginal and chief
// rays' heights together, within where their sag is defined. Throws LensTableError when the stop
// needs one and the file states no aperture.
void setAutomaticApertures(LensSystem& lens, const LensTable& table);

// The paraxial effective focal length along the unfolded axis (vertex curvatures, z gaps, indices
// at the lens's wavelength); infinity for an afocal lens.
double paraxialFocalLength(const LensSystem& lens);

}  // namespace lenslab
