#include "integrators/DirectLightingIntegrator.h"

#include <limits>

namespace lenslab {

Vec3f DirectLightingIntegrator::directLight(const Intersection& it, const Bsdf& bsdf, Vec3f wo, Pcg32& rng,
                                            std::uint64_t& raysTraced) const {
    Vec3f L;
    for (const auto& light : geometry_.lights()) {
        const float u1 = rng.uniform(), u2 = rng.uniform();
        L += lightSampleEstimate(geometry_, it, bsdf, wo, *light, 1.0f, u1, u2, weighting_, raysTraced);
        if (weighting_ == LightSampleWeight::Mis) {
            const float uLobe = rng.uniform(), v1 = rng.uniform(), v2 = rng.uniform();
            L += bsdfSampleEstimate(geometry_, it, bsdf, wo, *light, uLobe, v1, v2, raysTraced);
        }
    }
    return L;
}

Vec3f DirectLightingIntegrator::radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng,
                                         std::uint64_t& raysTraced) const {
    Vec3f L{}, beta{1, 1, 1};
    Vec3f o = origin, d = direction;
    for (int depth = 0;; ++depth) {
        Intersection it;
        ++raysTraced;
        if (!geometry_.intersect(o, d, std::numeric_limits<float>::infinity(), time, it)) {
            L += beta * environmentRadiance(geometry_, d);
            break;
        }
        if (it.light) L += beta * it.light->emitted(&it.hit, d);
        const Vec3f wo = -d;
        const Bsdf bsdf(it.hit, *it.material);
        if (!it.material->isSpecular()) L += beta * directLight(it, bsdf, wo, rng, raysTraced);
        if (depth + 1 >= maxDepth_) break;
        BsdfSample bs;
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!bsdf.sample(wo, uLobe, u1, u2, bs) || !bs.specular || isBlack(bs.weight)) break;
        beta *= bs.weight;
        o = offsetRayOrigin(it.hit, bs.wi);
        d = bs.wi;
    }
    return allFinite(L) ? L : Vec3f{};
}

}  // namespace lenslab
