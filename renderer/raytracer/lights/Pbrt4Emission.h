#pragma once
// How pbrt-v4 reads a light's emission: a spectrum (blackbody, sampled, named, .spd) is normalised
// to luminance 1 before "scale" multiplies it, while an RGB value keeps its own magnitude (only
// its illuminant, the colour space's white of luminance 1, is normalised). Absent, the emission is
// that white. "power" and "illuminance" then rescale so that the light delivers them.
#include <string>

#include "core/ParamSet.h"

namespace lenslab {

// The parameter `name` as pbrt-v4 normalises it, times "scale" (pbrt-v4's scale is one number).
Vec3f pbrt4Emission(const ParamSet& p, const std::string& name);

// pbrt-v4's "power": the factor P / unitPower, unitPower being what the light emits in all when its
// emission has luminance 1 (4 pi for a point light); 1 without "power". It multiplies "scale" and
// the RGB value alike, as in pbrt-v4, so only a white light delivers exactly P.
float pbrt4PowerFactor(const ParamSet& p, float unitPower);

}  // namespace lenslab
