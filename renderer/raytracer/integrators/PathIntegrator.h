#pragma once
// Unidirectional path tracing with next-event estimation: at every diffuse or glossy vertex one
// light is sampled (chosen in proportion to its power) and combined with the BSDF-sampled
// continuation by multiple importance sampling (power heuristic); Russian roulette ends long paths.
#include "integrators/Integrator.h"
#include "lights/LightSampler.h"

namespace lenslab {

class PathIntegrator : public Integrator {
public:
    PathIntegrator(const SceneGeometry& geometry, int maxDepth)
        : geometry_(geometry), lightSampler_(geometry.lights()), maxDepth_(maxDepth) {}
    Vec3f radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const override;

private:
    // The solid-angle pdf with which next-event estimation from `from` picks direction w toward
    // `light` (meeting it at `at`, or escaping): the light's own pdf times its choice probability.
    float lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const;

    const SceneGeometry& geometry_;
    LightSampler lightSampler_;
    int maxDepth_;
};

}  // namespace lenslab
