#pragma once
// pbrt-v3's "directlighting" and "whitted" integrators. Both add, at each surface a camera ray or a
// chain of perfect specular bounces reaches, its emission and the direct light of every light
// source, then follow only perfect specular reflection and transmission while fewer than maxDepth
// surfaces have been met. Whitted takes one light sample per light; directlighting adds a BSDF
// sample per light and combines the two by multiple importance sampling.
//
// pbrt-v3 follows a glass surface's reflection and transmission both; here one of them is chosen
// per visit by the material's own sampling (weighted by its probability), which has the same mean.
#include "integrators/DirectLight.h"
#include "integrators/Integrator.h"

namespace lenslab {

class DirectLightingIntegrator : public Integrator {
public:
    DirectLightingIntegrator(const SceneGeometry& geometry, int maxDepth, LightSampleWeight weighting)
        : geometry_(geometry), maxDepth_(maxDepth), weighting_(weighting) {}
    Vec3f radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const override;

private:
    Vec3f directLight(const Intersection& it, const Bsdf& bsdf, Vec3f wo, Pcg32& rng, std::uint64_t& raysTraced) const;

    const SceneGeometry& geometry_;
    int maxDepth_;
    LightSampleWeight weighting_;
};

}  // namespace lenslab
