#pragma once
// Rough lobes from microfacet theory (Torrance-Sparrow reflection, Walter et al. 2007
// transmission) and Ashikhmin-Shirley's Fresnel-blended diffuse + glossy pair, as pbrt-v3 defines
// them.
#include "materials/Bsdf.h"
#include "materials/Fresnel.h"
#include "materials/Microfacet.h"

namespace lenslab {

// D G F / (4 |cos o| |cos i|). Weight: the colour (Ks, Kr; 1 for metals, whose colour is F).
class MicrofacetReflection final : public Lobe {
public:
    MicrofacetReflection(MicrofacetDistribution d, Fresnel fresnel) : d_(d), fresnel_(fresnel) {}
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
    float pdf(Vec3f wo, Vec3f wi) const override;
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    MicrofacetDistribution d_;
    Fresnel fresnel_;
};

// Refraction through a rough boundary from index etaA (the normal's side) into etaB, for radiance
// (Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007).
// Weight: the colour Kt.
class MicrofacetTransmission final : public Lobe {
public:
    MicrofacetTransmission(MicrofacetDistribution d, float etaA, float etaB) : d_(d), etaA_(etaA), etaB_(etaB) {}
    unsigned type() const override { return kTransmission; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
    float pdf(Vec3f wo, Vec3f wi) const override;
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    // The microfacet normal that refracts wi into wo (on the normal's side), and the ratio
    // eta(wi's side) / eta(wo's side); false when no facet does.
    bool halfVector(Vec3f wo, Vec3f wi, Vec3f& wh, float& eta) const;

    MicrofacetDistribution d_;
    float etaA_, etaB_;
};

// A glossy coat over a diffuse base whose diffuse share falls as the coat's Schlick Fresnel rises
// (Ashikhmin & Shirley, "An Anisotropic Phong BRDF Model", 2000; pbrt-v3's substrate).
// Weight: the mix share (Rd and Rs are inside).
class FresnelBlend final : public Lobe {
public:
    FresnelBlend(Vec3f rd, Vec3f rs, MicrofacetDistribution d) : rd_(rd), rs_(rs), d_(d) {}
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override;
    float pdf(Vec3f wo, Vec3f wi) const override;
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    Vec3f rd_, rs_;
    MicrofacetDistribution d_;
};

}  // namespace lenslab
