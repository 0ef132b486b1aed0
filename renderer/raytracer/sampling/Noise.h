#pragma once
// Ken Perlin's gradient noise and the sums of its octaves that pbrt-v3's procedural textures use
// (fractional Brownian motion and turbulence).
#include "core/Vec3f.h"

namespace lenslab {

// Perlin's "improved noise" (SIGGRAPH 2002): zero at integer lattice points, roughly in [-1, 1].
float perlinNoise(Vec3f p);

// The noise's gradient by forward differences over 0.01, as pbrt-v4's DNoise takes it.
Vec3f perlinNoiseGradient(Vec3f p);

// pbrt-v3 sums octaves until the texture's screen footprint; lenslab traces no ray differentials,
// so every point gets all `octaves` (what pbrt-v3 does for a zero footprint).
// sum of omega^i noise(1.99^i p)
float fractionalBrownianMotion(Vec3f p, float omega, int octaves);
// sum of omega^i |noise(1.99^i p)|, plus pbrt-v3's stand-in 0.2 omega^octaves for the octaves
// beyond the footprint.
float turbulence(Vec3f p, float omega, int octaves);

}  // namespace lenslab
