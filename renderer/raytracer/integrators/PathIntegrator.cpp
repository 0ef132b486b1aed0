#include "integrators/PathIntegrator.h"

#include <cmath>
#include <limits>

#include "integrators/DirectLight.h"

namespace lenslab {

float PathIntegrator::lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const {
    return light.pdf(from, w, at) * lightSampler_.probability(light);
}

Vec3f PathIntegrator::radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const {
    Vec3f L{}, beta{1, 1, 1};
    Vec3f o = origin, d = direction;
    bool lastSpecular = true;  // the camera ray counts as specular: emission seen directly is unweighted
    float lastPdf = 0;
    Vec3f lastP = origin;
    for (int depth = 0;; ++depth) {
        Intersection it;
        ++raysTraced;
        const bool hit = geometry_.intersect(o, d, std::numeric_limits<float>::infinity(), time, it);
        if (!hit) {
            for (const auto& light : geometry_.lights()) {
                if (!light->isInfinite()) continue;
                const Vec3f Le = light->emitted(nullptr, d);
                const float w = lastSpecular ? 1.0f : powerHeuristic(lastPdf, lightPdf(*light, lastP, d, nullptr));
                L += w * beta * Le;
            }
            break;
        }
        if (it.light) {
            const Vec3f Le = it.light->emitted(&it.hit, d);
            const float w = lastSpecular ? 1.0f : powerHeuristic(lastPdf, lightPdf(*it.light, lastP, d, &it.hit));
            L += w * beta * Le;
        }
        if (depth >= maxDepth_) break;
        const Vec3f wo = -d;
        const Bsdf bsdf(it.hit, *it.material);
        if (!it.material->isSpecular()) {
            float choicePdf;
            const float uChoice = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
            if (const Light* light = lightSampler_.choose(uChoice, choicePdf))
                L += beta * lightSampleEstimate(geometry_, it, bsdf, wo, *light, choicePdf, u1, u2, LightSampleWeight::Mis,
                                                raysTraced);
        }
        BsdfSample bs;
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!bsdf.sample(wo, uLobe, u1, u2, bs) || isBlack(bs.weight)) break;
        beta *= bs.weight;
        lastSpecular = bs.specular;
        lastPdf = bs.pdf;
        lastP = it.hit.p;
        o = offsetRayOrigin(it.hit, bs.wi);
        d = bs.wi;
        if (depth >= 3) {  // Russian roulette keeps long paths unbiased and cheap
            const float q = std::min(0.95f, maxComponent(beta));
            if (rng.uniform() >= q) break;
            beta = beta / q;
        }
    }
    return allFinite(L) ? L : Vec3f{};
}

}  // namespace lenslab
