#pragma once
// Surface scattering with pbrt-v3's materials, parameters and defaults: matte, plastic, metal,
// mirror, glass, substrate, uber, translucent, mix, measured and none/interface.
// Directions point away from the surface, in world space.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "textures/Texture.h"
#include "core/Vec3f.h"

namespace lenslab {

struct SurfaceHit {
    Vec3f p;        // world position, metres
    Vec3f ng;       // geometric normal (unit), as the shape orients it
    Vec3f ns;       // shading normal (unit, same side as ng)
    // pbrt-v3's shading partials of p along u and v: the surface's own, except on meshes with
    // shading normals, where pbrt-v3 takes unit tangents around ns (both pointing against the
    // surface's partials: pbrt-v3 issues #188 and #261, kept there and so here). Zero when the shape
    // gives none.
    Vec3f dpdu, dpdv;
    // pbrt-v3's partials of the normal along u and v, which bump mapping needs for the displacement
    // times the normal's turning: on quadrics those of ns itself (Weingarten equations; through a
    // scaling transform and ReverseOrientation they stay the partials of the oriented unit normal,
    // where pbrt-v3's are not), on meshes with shading normals those of the interpolated vertex
    // normals; zero on flat shapes and curves, as in pbrt-v3.
    Vec3f dndu, dndv;
    float u = 0, v = 0;
};

struct BsdfSample {
    Vec3f wi;
    Vec3f weight;       // f * |cos| / pdf
    float pdf = 0;      // solid angle; for a specular sample, the probability of choosing it
    bool specular = false;
};

// The scattering volume behind a surface whose material has one (pbrt's "subsurface"): a
// homogeneous medium, coefficients per unit of scene length, taken where a path enters.
struct InteriorMedium {
    Vec3f sigmaA, sigmaS;
    float g = 0;  // Henyey-Greenstein
};

class Bsdf;

class Material {
public:
    virtual ~Material() = default;
    // Lays this material's lobes at `hit` into `bsdf`, their weights multiplied by `scale` (a mix
    // material scales the lobes of its two parts).
    virtual void addLobes(const SurfaceHit& hit, Vec3f scale, Bsdf& bsdf) const = 0;
    // The most lobes addLobes may add, so that a mix can be checked to fit in one Bsdf.
    virtual int maxLobes() const = 0;
    // True when every lobe is specular wherever the material is hit: light sampling is pointless.
    virtual bool isSpecular() const { return false; }
    // No surface at all ("interface", "none", ""): only a boundary between media. The volumetric
    // path tracer passes such hits without counting a bounce, as pbrt does.
    virtual bool isPassthrough() const { return false; }
    // A scattering volume behind the surface, on the side its normal points away from: the
    // volumetric path tracer enters it when a path is transmitted inward (subsurface scattering).
    virtual bool hasInterior() const { return false; }
    virtual InteriorMedium interiorAt(const SurfaceHit&) const { return {}; }

    // f(wo, wi) |cos(wi, ns)|; zero for specular lobes.
    Vec3f evaluate(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const;
    float pdf(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const;
    bool sample(const SurfaceHit& hit, Vec3f wo, float uLobe, float u1, float u2, BsdfSample& out) const;

    // pbrt-v3's "bumpmap": the float texture displaces the surface along its shading normal; hits
    // of this material take the displaced surface's normal and partials (applyBump, once per hit).
    void setBumpMap(std::shared_ptr<const Texture> displacement) { bump_ = std::move(displacement); }
    bool hasBumpMap() const { return bump_ != nullptr; }
    void applyBump(SurfaceHit& hit) const;

private:
    std::shared_ptr<const Texture> bump_;
};

using NamedMaterials = std::map<std::string, std::shared_ptr<const Material>>;

// What a material definition may refer to: declared textures, named materials (for "mix"), files
// (for "measured"), and where warnings go.
struct MaterialContext {
    const TextureMap& textures;
    const NamedMaterials& named;
    PathResolver resolve;
    std::vector<std::string>& warnings;
};

// Material "TYPE" params (or MakeNamedMaterial's "string type"). Unknown types are a SceneError.
std::shared_ptr<const Material> makeMaterial(const std::string& type, const ParamSet& params,
                                             const MaterialContext& context);

std::shared_ptr<const Material> makeDefaultMaterial();  // matte, Kd 0.5

}  // namespace lenslab
