#pragma once
// Entrance and exit pupils: the paraxial images of the aperture stop through the elements in front
// of it (seen from the scene) and behind it (seen from the film).
#include "prescription/LensSystem.h"

namespace lenslab {

struct Pupil {
    double z = 0;         // mm, lens convention
    double diameter = 0;  // mm, for the stop's current opening
    double magnification = 0;  // pupil size / stop size (signed)
};

struct Pupils {
    Pupil entrance;
    Pupil exit;
};

// Uses the stop's current aperture radius. Throws OpticsError for a telecentric side (pupil at
// infinity) or when near-axis rays cannot pass.
Pupils computePupils(const LensSystem& lens);

}  // namespace lenslab
