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

}  // namespace lenslab
