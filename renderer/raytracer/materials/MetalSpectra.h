#pragma once
// Named spectra for metal (and metal-oxide) optical constants, as pbrt's scene files name them:
// "metal-Cu-eta", "metal-Cu-k", and likewise Ag, Al, Au, CuZn (brass), MgO, TiO2.
#include <optional>
#include <string>

#include "core/Vec3f.h"

namespace lenslab {

// The spectrum converted to the renderer's RGB (as sampledSpectrumToRgb does for any sampled
// spectrum), or nothing when `name` is not one of them.
std::optional<Vec3f> namedSpectrumRgb(const std::string& name);

}  // namespace lenslab
