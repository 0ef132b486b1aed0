#pragma once
// Measured scattering coefficients of everyday materials, by the names pbrt's scenes use
// ("Skin1", "Ketchup", "Regular Milk", ...): pbrt-v4's subsurface "name" and pbrt's homogeneous
// medium "preset". RGB values per millimetre, measured by Jensen, Marschner, Levoy & Hanrahan, "A
// Practical Model for Subsurface Light Transport" (SIGGRAPH 2001), and by Narasimhan, Gupta,
// Donner, Ramamoorthi, Nayar & Jensen, "Acquiring Scattering Properties of Participating Media by
// Dilution" (SIGGRAPH 2006), under the names and in the RGB form pbrt-v3 and pbrt-v4 list them.
#include <optional>
#include <string>

#include "core/Vec3f.h"

namespace lenslab {

struct MeasuredMedium {
    Vec3f sigmaA;       // absorption, mm^-1
    Vec3f sigmaSPrime;  // reduced scattering sigma_s (1 - g), mm^-1: used as isotropic scattering
};

std::optional<MeasuredMedium> measuredMedium(const std::string& name);

}  // namespace lenslab
