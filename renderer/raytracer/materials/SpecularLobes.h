#pragma once
// Perfectly smooth lobes (deltas, only ever sampled): mirror reflection with a Fresnel factor,
// refraction through a dielectric boundary, and the two together chosen by Fresnel reflectance.
#include "materials/Bsdf.h"
#include "materials/Fresnel.h"

namespace lenslab {

// Weight: the colour Kr.
class SpecularReflection final : public Lobe {
public:
    explicit SpecularReflection(Fresnel fresnel) : fresnel_(fresnel) {}
    unsigned type() const override { return kReflection | kSpecular; }
    Vec3f f(Vec3f, Vec3f) const override { return {}; }
    float pdf(Vec3f, Vec3f) const override { return 0; }
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    Fresnel fresnel_;
};

// Refraction from index etaA (the normal's side) into etaB, times 1 - Fresnel reflectance.
// Radiance carried across is scaled by (eta_from / eta_to)^2 (it is concentrated in the denser
// medium). etaA == etaB passes light straight through: uber's opacity and the "none" material.
// Weight: the colour Kt.
class SpecularTransmission final : public Lobe {
public:
    SpecularTransmission(float etaA, float etaB) : etaA_(etaA), etaB_(etaB) {}
    unsigned type() const override { return kTransmission | kSpecular; }
    Vec3f f(Vec3f, Vec3f) const override { return {}; }
    float pdf(Vec3f, Vec3f) const override { return 0; }
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    float etaA_, etaB_;
};

// A smooth dielectric boundary: reflection with probability F, refraction with 1 - F, so that
// each path carries only the colour (pbrt-v3's FresnelSpecular). Weight: the mix share.
class FresnelSpecular final : public Lobe {
public:
    FresnelSpecular(Vec3f r, Vec3f t, float etaA, float etaB) : r_(r), t_(t), etaA_(etaA), etaB_(etaB) {}
    unsigned type() const override { return kReflection | kTransmission | kSpecular; }
    Vec3f f(Vec3f, Vec3f) const override { return {}; }
    float pdf(Vec3f, Vec3f) const override { return 0; }
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    Vec3f r_, t_;
    float etaA_, etaB_;
};

// A thin dielectric sheet (pbrt-v4's thindielectric): light bounces between its two faces, so it
// reflects R + T^2 R / (1 - R^2) and the rest passes straight through, unbent. One is chosen in
// proportion to its share.
class ThinDielectric final : public Lobe {
public:
    explicit ThinDielectric(float eta) : eta_(eta) {}
    unsigned type() const override { return kReflection | kTransmission | kSpecular; }
    Vec3f f(Vec3f, Vec3f) const override { return {}; }
    float pdf(Vec3f, Vec3f) const override { return 0; }
    bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const override;

private:
    float eta_;
};

}  // namespace lenslab
