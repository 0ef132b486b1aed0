#pragma once
// A central obscuration as the axial pupil sees it: the radius, as a fraction of the pupil's, inside
// which the rays of the axial field are blocked (a reflex lens's secondary mirror, a Cassegrain's
// central hole). It sets the annular pupil's diffraction limit (DiffractionMtf.h).
#include "analysis/PupilAiming.h"
#include "prescription/LensSystem.h"

namespace lenslab {

// 0 when the axial ray passes; found by bisection on the normalised stop radius between the blocked
// centre and the first passing radius (a tangential sweep: obscurations are round and centred).
double axialObscuration(const LensSystem& lens, const FieldAim& axis);

}  // namespace lenslab
