#include "PathIntegrator.h"

#include <cmath>
#include <limits>

namespace lenslab {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Moves a ray origin off the surface, to the side the ray leaves toward, against self-hits.
Vec3f offsetOrigin(const SurfaceHit& h, Vec3f w) {
    const float eps = 1e-4f * std::max(1.0f, maxComponent({std::fabs(h.p.x), std::fabs(h.p.y), std::fabs(h.p.z)}));
    return h.p + (dot(w, h.ng) > 0 ? eps : -eps) * h.ng;
}

}  // namespace

float PathIntegrator::lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const {
    return light.pdf(from, w, at) / float(geometry_.lights().size());
}

Vec3f PathIntegrator::sampleOneLight(const Intersection& it, Vec3f wo, Pcg32& rng, std::uint64_t& raysTraced) const {
    const auto& lights = geometry_.lights();
    if (lights.empty()) return {};
    const std::size_t n = lights.size();
    const std::size_t index = std::min<std::size_t>(std::size_t(rng.uniform() * n), n - 1);
    const Light& light = *lights[index];
    const float u1 = rng.uniform(), u2 = rng.uniform();
    LightSample ls;
    if (!light.sample(it.hit.p, u1, u2, ls) || isBlack(ls.radiance)) return {};
    const Vec3f f = it.material->evaluate(it.hit, wo, ls.wi);
    if (isBlack(f)) return {};
    const Vec3f o = offsetOrigin(it.hit, ls.wi);
    const float tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0f - 1e-3f);
    ++raysTraced;
    if (geometry_.occluded(o, ls.wi, tMax)) return {};
    const float pdfLight = ls.pdf / float(n);
    if (ls.delta) return f * ls.radiance / pdfLight;
    const float w = powerHeuristic(pdfLight, it.material->pdf(it.hit, wo, ls.wi));
    return w * f * ls.radiance / pdfLight;
}

Vec3f PathIntegrator::radiance(Vec3f origin, Vec3f direction, Pcg32& rng, std::uint64_t& raysTraced) const {
    Vec3f L{}, beta{1, 1, 1};
    Vec3f o = origin, d = direction;
    bool lastSpecular = true;  // the camera ray counts as specular: emission seen directly is unweighted
    float lastPdf = 0;
    Vec3f lastP = origin;
    bool afterDiffuse = false;  // directlighting: only the emission a BSDF sample hits next still counts
    for (int depth = 0;; ++depth) {
        Intersection it;
        ++raysTraced;
        const bool hit = geometry_.intersect(o, d, kInf, it);
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
        if (afterDiffuse || depth >= spec_.maxDepth) break;
        const Vec3f wo = -d;
        if (!it.material->isSpecular()) L += beta * sampleOneLight(it, wo, rng, raysTraced);
        BsdfSample bs;
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!it.material->sample(it.hit, wo, uLobe, u1, u2, bs) || isBlack(bs.weight)) break;
        beta *= bs.weight;
        lastSpecular = bs.specular;
        lastPdf = bs.pdf;
        lastP = it.hit.p;
        if (spec_.type == IntegratorType::DirectLighting && !bs.specular) afterDiffuse = true;
        o = offsetOrigin(it.hit, bs.wi);
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
