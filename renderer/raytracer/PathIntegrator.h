#pragma once
// Unidirectional path tracing with next-event estimation: at every diffuse or glossy vertex one
// light is sampled (uniformly chosen) and combined with the BSDF-sampled continuation by multiple
// importance sampling (power heuristic). "directlighting" stops after the first such vertex.
#include <cstdint>

#include "SceneDescription.h"
#include "SceneGeometry.h"
#include "Sampling.h"

namespace lenslab {

class PathIntegrator {
public:
    PathIntegrator(const SceneGeometry& geometry, const IntegratorSpec& spec) : geometry_(geometry), spec_(spec) {}
    // Radiance arriving along the ray (world space). raysTraced counts closest-hit and shadow rays.
    Vec3f radiance(Vec3f origin, Vec3f direction, Pcg32& rng, std::uint64_t& raysTraced) const;

private:
    Vec3f sampleOneLight(const Intersection& it, Vec3f wo, Pcg32& rng, std::uint64_t& raysTraced) const;
    float lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const;

    const SceneGeometry& geometry_;
    IntegratorSpec spec_;
};

}  // namespace lenslab
