#pragma once
// Diffuse lobes (weights carry their colours): Lambertian reflection and transmission, and
// Oren-Nayar's rough diffuse reflection (the qualitative model, as pbrt-v3 uses it).
#include "materials/Bsdf.h"

namespace lenslab {

class LambertianReflection final : public Lobe {
public:
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
};

class LambertianTransmission final : public Lobe {
public:
    unsigned type() const override { return kTransmission; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
    float pdf(Vec3f wo, Vec3f wi) const override;  // cosine-weighted on the far side
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;
};

// sigma: standard deviation of the facet slope angle, degrees (pbrt-v3's "sigma"; 0 is Lambert).
class OrenNayar final : public Lobe {
public:
    explicit OrenNayar(float sigmaDegrees);
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;

private:
    float a_, b_;
};

// The diffuse base of a coated surface seen through a smooth dielectric coat of index eta
// (lenslab's closed-form stand-in for pbrt-v4's stochastic layered coateddiffuse): light enters
// through 1 - F, is reflected diffusely with the base's reflectance, bounces between base and coat
// (the coat reflects Fdr of diffuse light back: the 1 / (1 - R Fdr) series), leaves through 1 - F
// spread over eta^2 more solid angle, and crosses the coat's thickness at the refracted angles with
// pbrt-v4's transmittance exp(-thickness / cos). Energy-conserving; reciprocal. The coat's own
// reflection is a separate lobe.
class CoatedDiffuse final : public Lobe {
public:
    // internalReflectance: the coat's hemispherical reflectance of diffuse light from inside
    // (coatInternalReflectance(eta)).
    CoatedDiffuse(Vec3f reflectance, float eta, float thickness, float internalReflectance)
        : reflectance_(reflectance), eta_(eta), thickness_(thickness), internal_(internalReflectance) {}
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;

private:
    float throughCoat(float cosOutside) const;  // (1 - F) times the layer's transmittance
    Vec3f reflectance_;
    float eta_, thickness_, internal_;
};

// The hemispherical average reflectance of a smooth boundary for diffuse light arriving from
// inside a medium of index eta (1 - (1 - Fdr outside) / eta^2, by reciprocity).
float coatInternalReflectance(float eta);

}  // namespace lenslab
