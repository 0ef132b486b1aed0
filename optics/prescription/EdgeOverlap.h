#pragma once
// Neighbouring surfaces that cross before the edge of their clear apertures: a mechanical matter
// the designer fixes (an edge thickness below zero at the stated diameter), so the lens still
// reads, with a warning, and rays are clipped where the two solids would cut into each other.
#include "prescription/LensSystem.h"

namespace lenslab {

// For each pair of neighbouring centred surfaces: where they cross inside both apertures, warns
// (naming both surfaces' lines, the crossing height and the edge thickness at the stated diameter)
// and closes both apertures to the crossing height. Automatic apertures are closed without a
// warning (the file stated none). Throws LensTableError when they cross at the axis itself.
void clipOverlappingEdges(LensSystem& lens);

}  // namespace lenslab
