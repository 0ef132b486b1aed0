#pragma once
// The equal-area octahedral map between the unit square and the sphere (Clarberg, "Fast
// equal-area mapping of the (hemi)sphere using SIMD", 2008) that pbrt-v4 uses for environment maps
// and goniometric diagrams: equal areas of the square cover equal solid angles, so a texel's solid
// angle is 4 pi / texel count everywhere. The square's centre is +z, its corners -z.
#include "core/Vec3f.h"

namespace lenslab {

Vec3f equalAreaSquareToSphere(float u, float v);          // (u, v) in [0, 1]^2
void equalAreaSphereToSquare(Vec3f d, float& u, float& v);  // d: unit vector

}  // namespace lenslab
