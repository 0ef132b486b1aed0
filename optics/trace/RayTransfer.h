#pragma once
// Paraxial ray-transfer (ABCD) matrices through a lens's surfaces as they are met in sequence,
// mirrors included: a paraxial ray is its height y and its slope u = dy/ds along its own direction
// of travel, and (y, u) after = M (y, u) before. Only the vertex curvatures enter (first-order
// optics). A ghost's matrix is its unfolded lens's (trace/GhostPath.h).
#include "prescription/LensSystem.h"

namespace lenslab {

struct RayTransfer {
    double a = 1, b = 0, c = 0, d = 1;
    double height(double y, double u) const { return a * y + b * u; }
    double slope(double y, double u) const { return c * y + d * u; }
};

// `later` after `earlier`.
RayTransfer operator*(const RayTransfer& later, const RayTransfer& earlier);

// Through surfaces [0, end) from the plane z = zFrom in air in front of surface 0 (light travelling
// toward -z) to the plane z = zTo after surface end - 1, in the medium and the direction of travel
// there. Planes may lie inside the lens (a virtual pupil): the transfers are signed.
RayTransfer rayTransfer(const LensSystem& lens, double zFrom, int end, double zTo);

}  // namespace lenslab
