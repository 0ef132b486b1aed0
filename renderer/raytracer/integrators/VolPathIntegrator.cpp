#include "integrators/VolPathIntegrator.h"

#include <cmath>
#include <limits>

#include "integrators/DirectLight.h"

namespace lenslab {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
// Medium boundaries one ray may cross before it is given up (a guard against rays caught between
// coincident boundaries; real scenes cross a handful).
constexpr int kMaxCrossings = 256;

}  // namespace

// Where a path scatters: on a surface (its BSDF) or at a point in a medium (its phase function).
struct VolPathIntegrator::Vertex {
    Vec3f p, wo;                          // wo: back along the path
    const Intersection* surface;          // null: a point in `medium`
    const ParticipatingMedium* medium;                 // the medium the path travels in
    float time;                           // the camera ray's moment, kept by every ray of the path

    Vec3f f(Vec3f wi) const {
        if (surface) return surface->material->evaluate(surface->hit, wo, wi);
        const float phase = medium->phase().evaluate(-wo, wi);
        return {phase, phase, phase};
    }
    float pdf(Vec3f wi) const {
        return surface ? surface->material->pdf(surface->hit, wo, wi) : medium->phase().evaluate(-wo, wi);
    }
    Vec3f origin(Vec3f wi) const { return surface ? offsetRayOrigin(surface->hit, wi) : p; }
    const ParticipatingMedium* mediumToward(Vec3f wi) const {
        return surface && surface->media->isTransition() ? surface->media->leaving(wi, surface->hit.ng) : medium;
    }
};

float VolPathIntegrator::lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const {
    return light.pdf(from, w, at) * lightSampler_.probability(light);
}

Vec3f VolPathIntegrator::transmittance(Vec3f o, Vec3f w, float distance, float time, const ParticipatingMedium* medium,
                                       Pcg32& rng, std::uint64_t& raysTraced) const {
    Vec3f tr{1, 1, 1};
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        Intersection it;
        ++raysTraced;
        const bool hit = geometry_.intersect(o, w, distance, time, it);
        if (hit && !it.material->isPassthrough()) return {};
        if (medium) tr *= medium->transmittance(o, w, hit ? it.t : distance, rng);
        if (!hit || isBlack(tr)) return tr;
        if (it.media->isTransition()) medium = it.media->leaving(w, it.hit.ng);
        o = offsetRayOrigin(it.hit, w);
        distance -= it.t;
    }
    return {};
}

Vec3f VolPathIntegrator::sampleLight(const Vertex& v, Pcg32& rng, std::uint64_t& raysTraced) const {
    float choicePdf;
    const float uChoice = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const Light* light = lightSampler_.choose(uChoice, choicePdf);
    LightSample ls;
    if (!light || !(choicePdf > 0) || !light->sample(v.p, u1, u2, ls) || isBlack(ls.radiance) || !(ls.pdf > 0)) return {};
    const Vec3f f = v.f(ls.wi);
    if (isBlack(f)) return {};
    const float tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0f - 1e-3f);
    const Vec3f tr = transmittance(v.origin(ls.wi), ls.wi, tMax, v.time, v.mediumToward(ls.wi), rng, raysTraced);
    if (isBlack(tr)) return {};
    const float pdf = ls.pdf * choicePdf;
    const float w = ls.delta ? 1.0f : powerHeuristic(pdf, v.pdf(ls.wi));
    return w * f * tr * ls.radiance / pdf;
}

Vec3f VolPathIntegrator::radiance(Vec3f origin, Vec3f direction, float time, Pcg32& rng, std::uint64_t& raysTraced) const {
    Vec3f L{}, beta{1, 1, 1};
    Vec3f o = origin, d = direction;
    const ParticipatingMedium* medium = cameraMedium_;
    bool lastSpecular = true;  // the camera ray counts as specular: emission seen directly is unweighted
    float lastPdf = 0;
    Vec3f lastP = origin;
    int bounces = 0, crossings = 0;
    // The channel whose coefficients draw this path's distances; ratio: every channel's path density
    // over the hero's, kept at mean 1 by dividing beta too (ParticipatingMedium.h: spectral MIS).
    const int hero = std::min(int(rng.uniform() * 3), 2);
    Vec3f ratio{1, 1, 1};
    // Russian roulette past the third bounce keeps long paths unbiased and cheap.
    const auto survives = [&] {
        if (bounces <= 3) return true;
        const float q = std::min(0.95f, maxComponent(beta));
        if (rng.uniform() >= q) return false;
        beta = beta / q;
        return true;
    };
    for (;;) {
        Intersection it;
        ++raysTraced;
        const bool hit = geometry_.intersect(o, d, kInf, time, it);
        if (medium) {
            const MediumEvent e = medium->sample(o, d, hit ? it.t : kInf, hero, rng);
            ratio *= e.pdfRatio;
            const float meanRatio = (ratio.x + ratio.y + ratio.z) / 3;
            beta = beta * e.weight / meanRatio;
            ratio = ratio / meanRatio;
            if (isBlack(beta)) break;
            if (e.scattered) {
                if (bounces++ >= maxDepth_) break;
                const Vertex v{o + e.t * d, -d, nullptr, medium, time};
                L += beta * sampleLight(v, rng, raysTraced);
                const float u1 = rng.uniform(), u2 = rng.uniform();
                const Vec3f wi = medium->phase().sample(d, u1, u2);  // weight 1: sampled exactly
                lastSpecular = false;
                lastPdf = medium->phase().evaluate(d, wi);
                lastP = v.p;
                o = v.p;
                d = wi;
                if (!survives()) break;
                continue;
            }
        }
        if (!hit) {
            for (const auto& light : geometry_.lights()) {
                if (!light->isInfinite()) continue;
                const float w = lastSpecular ? 1.0f : powerHeuristic(lastPdf, lightPdf(*light, lastP, d, nullptr));
                L += w * beta * light->emitted(nullptr, d);
            }
            break;
        }
        if (it.light) {
            const float w = lastSpecular ? 1.0f : powerHeuristic(lastPdf, lightPdf(*it.light, lastP, d, &it.hit));
            L += w * beta * it.light->emitted(&it.hit, d);
        }
        if (it.material->isPassthrough()) {
            if (it.media->isTransition()) medium = it.media->leaving(d, it.hit.ng);
            o = offsetRayOrigin(it.hit, d);
            if (++crossings > kMaxCrossings) break;
            continue;
        }
        if (bounces++ >= maxDepth_) break;
        const Vertex v{it.hit.p, -d, &it, medium, time};
        if (!it.material->isSpecular()) L += beta * sampleLight(v, rng, raysTraced);
        BsdfSample bs;
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!it.material->sample(it.hit, v.wo, uLobe, u1, u2, bs) || isBlack(bs.weight)) break;
        beta *= bs.weight;
        lastSpecular = bs.specular;
        lastPdf = bs.pdf;
        lastP = it.hit.p;
        medium = v.mediumToward(bs.wi);
        o = offsetRayOrigin(it.hit, bs.wi);
        d = bs.wi;
        if (!survives()) break;
    }
    return allFinite(L) ? L : Vec3f{};
}

}  // namespace lenslab
