#pragma once
// Microfacet normal distributions in the local shading frame (z = shading normal), with pbrt-v3's
// parameters: Trowbridge-Reitz (GGX) and Beckmann, anisotropic widths alphaX along the tangent and
// alphaY along the bitangent, masking-shadowing after Smith (height-correlated form).
#include "core/Vec3f.h"

namespace lenslab {

enum class MicrofacetKind { TrowbridgeReitz, Beckmann };

// pbrt-v3's map from a user "roughness" in [0, 1] to alpha ("remaproughness" true); the same
// polynomial serves both distributions, as in pbrt-v3.
float roughnessToAlpha(float roughness);

class MicrofacetDistribution {
public:
    // Widths below 1e-3 are raised to it (as pbrt-v3): narrower lobes are not representable in float.
    MicrofacetDistribution(MicrofacetKind kind, float alphaX, float alphaY);

    float D(Vec3f wh) const;            // normal density: integral of D(wh) cos(theta_h) dwh = 1
    float lambda(Vec3f w) const;        // Smith's auxiliary function
    float G1(Vec3f w) const { return 1.0f / (1.0f + lambda(w)); }
    float G(Vec3f wo, Vec3f wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

    // A microfacet normal on wo's side: the normals visible from wo for Trowbridge-Reitz (Heitz
    // 2018), the whole distribution for Beckmann.
    Vec3f sampleWh(Vec3f wo, float u1, float u2) const;
    float pdf(Vec3f wo, Vec3f wh) const;  // density of sampleWh, per solid angle of wh

private:
    MicrofacetKind kind_;
    float alphaX_, alphaY_;
};

}  // namespace lenslab
