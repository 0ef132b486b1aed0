#pragma once
// pbrt-v4's "hair" material with its parameter names and defaults: the fibre's absorption from
// "sigma_a", from a "reflectance" (or "color") by Chiang 2016's inversion, or from "eumelanin" /
// "pheomelanin" concentrations (default: eumelanin 1.3), and "eta" 1.55, "beta_m" 0.3,
// "beta_n" 0.3, "alpha" 2 degrees. The offset across the fibre comes from the hit's v, as curves
// set it (v = (1 + h) / 2). The model is HairLobe.h's.
#include <memory>

#include "materials/Material.h"

namespace lenslab {

// Throws SceneError naming the line for values out of range.
std::shared_ptr<Material> makeHairMaterial(const ParamSet& params, const MaterialContext& context);

}  // namespace lenslab
