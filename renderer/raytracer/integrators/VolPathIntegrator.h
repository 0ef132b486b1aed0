#pragma once
// Path tracing through participating media (pbrt's "volpath"). Along each ray segment the medium
// the ray travels in decides, by its distance sampling, whether the path scatters in the volume
// (then the phase function continues it) or reaches the surface. Every scattering vertex, in a
// volume or on a surface, samples one light (chosen by power) with the transmittance to it through
// the media and medium boundaries on the way, combined with the phase or BSDF sample by multiple
// importance sampling as the surface path tracer does. Boundaries without a surface (the
// "interface" material) change the ray's medium and count no bounce. A path transmitted into a
// subsurface material walks through the homogeneous volume behind its surface (Material::
// interiorAt) until the boundary lets it out; the walk counts no bounces, as pbrt-v4's BSSRDF
// counts none, so maxdepth limits the bounces outside.
#include "integrators/Integrator.h"
#include "lights/LightSampler.h"

namespace lenslab {

class VolPathIntegrator : public Integrator {
public:
    VolPathIntegrator(const SceneGeometry& geometry, int maxDepth, const ParticipatingMedium* cameraMedium)
        : geometry_(geometry), lightSampler_(geometry.lights()), maxDepth_(maxDepth), cameraMedium_(cameraMedium) {}
    Vec3f radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const override;

private:
    struct Vertex;
    struct Interior;
    float lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const;
    // One light sample's MIS-weighted contribution at a scattering vertex, shadowed by surfaces and
    // attenuated by the media between.
    Vec3f sampleLight(const Vertex& v, Pcg32& rng, std::uint64_t& raysTraced) const;
    // Transmittance from o along unit w over `distance`, starting in `medium` and crossing medium
    // boundaries; zero when a surface blocks the way.
    Vec3f transmittance(Vec3f o, Vec3f w, float distance, float time, const ParticipatingMedium* medium, Pcg32& rng,
                        std::uint64_t& raysTraced) const;

    const SceneGeometry& geometry_;
    LightSampler lightSampler_;
    int maxDepth_;
    const ParticipatingMedium* cameraMedium_;
};

}  // namespace lenslab
