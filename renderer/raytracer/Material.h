#pragma once
// Surface scattering: matte, plastic, mirror and glass, with pbrt-v3's parameters and defaults.
// Directions point away from the surface, in world space.
#include <memory>
#include <string>
#include <vector>

#include "Texture.h"
#include "Vec3f.h"

namespace lenslab {

struct SurfaceHit {
    Vec3f p;        // world position, metres
    Vec3f ng;       // geometric normal (unit)
    Vec3f ns;       // shading normal (unit, same side as ng)
    float u = 0, v = 0;
};

struct BsdfSample {
    Vec3f wi;
    Vec3f weight;       // f * |cos| / pdf
    float pdf = 0;      // solid angle; meaningless for specular samples
    bool specular = false;
};

class Material {
public:
    virtual ~Material() = default;
    // f(wo, wi) |cos(wi, ns)|; zero for purely specular materials.
    virtual Vec3f evaluate(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const = 0;
    virtual float pdf(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const = 0;
    virtual bool sample(const SurfaceHit& hit, Vec3f wo, float uLobe, float u1, float u2, BsdfSample& out) const = 0;
    // True when only specular lobes remain: light sampling is pointless there.
    virtual bool isSpecular() const { return false; }
};

// Material "TYPE" params (or MakeNamedMaterial's "string type"): matte, plastic, mirror, glass.
std::shared_ptr<const Material> makeMaterial(const std::string& type, const ParamSet& params, const TextureMap& textures,
                                             std::vector<std::string>& warnings);

std::shared_ptr<const Material> makeDefaultMaterial();  // matte, Kd 0.5

}  // namespace lenslab
