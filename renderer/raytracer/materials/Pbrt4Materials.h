#pragma once
// pbrt-v4's materials with its parameter names and defaults: diffuse, conductor, dielectric,
// thindielectric, diffusetransmission, coateddiffuse and coatedconductor (the layered two by a
// closed-form model, docs/pbrt-v4.md), subsurface (a dielectric over a scattering volume,
// docs/media.md), hair (HairMaterial.h). pbrt-v4's mix and "displacement" are read in Materials.cpp.
#include <memory>
#include <string>

#include "materials/Material.h"

namespace lenslab {

bool isPbrt4MaterialName(const std::string& type);

// For a type isPbrt4MaterialName accepts.
std::shared_ptr<Material> makePbrt4Material(const std::string& type, const ParamSet& params, const MaterialContext& context);

}  // namespace lenslab
