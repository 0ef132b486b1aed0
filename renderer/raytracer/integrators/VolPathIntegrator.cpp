#include "integrators/VolPathIntegrator.h"

#include <cmath>
#include <limits>
#include <optional>

#include "integrators/DirectLight.h"
#include "media/HomogeneousMedium.h"

namespace lenslab {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
// Medium boundaries one ray may cross before it is given up (a guard against rays caught between
// coincident boundaries; real scenes cross a handful).
constexpr int kMaxCrossings = 256;
// Scattering events one path may have inside subsurface volumes, which do not count against
// maxdepth (as pbrt-v4's BSSRDF counts none): a guard for media that hardly absorb.
constexpr int kMaxInteriorEvents = 1 << 16;

}  // namespace

// The volume behind a subsurface material's surface that a path is in: a homogeneous medium with
// the material's coefficients where the path entered, and the medium it returns to on leaving.
struct VolPathIntegrator::Interior {
    std::optional<HomogeneousMedium> medium;
    const ParticipatingMedium* enclosing = nullptr;
    bool inside = false;
    int events = 0;  // scatterings and boundary hits inside, over the whole path

    // The medium a shadow ray leaving the surface of `it` along w starts in. (Inward from outside
    // it meets the surface's far side, whatever the medium.)
    const ParticipatingMedium* toward(const Intersection& it, Vec3f w, const ParticipatingMedium* current) const {
        if (!inside) return current;
        return dot(w, it.hit.ng) < 0 ? &*medium : enclosing;
    }
    // After the BSDF at `it` turned a ray arriving along d into one leaving along wi: the medium
    // the path goes on in, entering the volume (with the coefficients at this point) or leaving it.
    const ParticipatingMedium* cross(const Intersection& it, Vec3f d, Vec3f wi, const ParticipatingMedium* current) {
        const bool fromOutside = dot(d, it.hit.ng) < 0, inward = dot(wi, it.hit.ng) < 0;
        if (inward && (fromOutside || !inside)) {
            const InteriorMedium m = it.material->interiorAt(it.hit);
            medium.emplace(m.sigmaA, m.sigmaS, HenyeyGreenstein(m.g));
            if (!inside) enclosing = it.media->isTransition() ? it.media->outside.get() : current;
            inside = true;
        } else if (!inward && !fromOutside && inside) {
            inside = false;
            return enclosing;
        }
        return inward ? &*medium : current;
    }
};

// Where a path scatters: on a surface (its BSDF) or at a point in a medium (its phase function).
struct VolPathIntegrator::Vertex {
    Vec3f p, wo;                        // wo: back along the path
    const Intersection* surface;        // null: a point in `medium`
    const Bsdf* bsdf;                   // the surface's
    const ParticipatingMedium* medium;  // the medium the path travels in
    float time;                         // the camera ray's moment, kept by every ray of the path
    const Interior* interior;           // for a surface with a scattering volume behind it

    // f |cos| (the phase function in a medium), and in `pdf` the density of sampling wi here.
    Vec3f f(Vec3f wi, float& pdf) const {
        if (surface) return bsdf->evaluate(wo, wi, pdf);
        pdf = medium->phase().evaluate(-wo, wi);
        return {pdf, pdf, pdf};
    }
    Vec3f origin(Vec3f wi) const { return surface ? offsetRayOrigin(surface->hit, wi) : p; }
    const ParticipatingMedium* mediumToward(Vec3f wi) const {
        if (!surface) return medium;
        if (interior) return interior->toward(*surface, wi, medium);
        return surface->media->isTransition() ? surface->media->leaving(wi, surface->hit.ng) : medium;
    }
};

float VolPathIntegrator::lightPdf(const Light& light, Vec3f from, Vec3f w, const SurfaceHit* at) const {
    return light.pdf(from, w, at) * lightSampler_.probability(light);
}

Vec3f VolPathIntegrator::transmittance(Vec3f o, Vec3f w, float distance, float time, const ParticipatingMedium* medium,
                                       Pcg32& rng, std::uint64_t& raysTraced) const {
    if (!geometry_.hasPassthroughSurfaces()) {  // any hit blocks: the cheaper any-hit query answers
        ++raysTraced;
        if (geometry_.occluded(o, w, distance, time)) return {};
        return medium ? medium->transmittance(o, w, distance, rng) : Vec3f{1, 1, 1};
    }
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
    float scatterPdf;
    const Vec3f f = v.f(ls.wi, scatterPdf);
    if (isBlack(f)) return {};
    const float tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0f - 1e-3f);
    const Vec3f tr = transmittance(v.origin(ls.wi), ls.wi, tMax, v.time, v.mediumToward(ls.wi), rng, raysTraced);
    if (isBlack(tr)) return {};
    const float pdf = ls.pdf * choicePdf;
    const float w = ls.delta ? 1.0f : powerHeuristic(pdf, scatterPdf);
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
    // Inside a subsurface volume, a walk of many events: Russian roulette only once the throughput
    // has fallen below 1 (pbrt-v4's rule), which keeps the weights near 1 however long the walk.
    Interior interior;
    const auto survivesInside = [&] {
        const float q = maxComponent(beta);
        if (q >= 1) return true;
        if (rng.uniform() >= q) return false;
        beta = beta / q;
        return true;
    };
    // Counts a scattering event: a bounce, or inside a subsurface volume one more step of its walk.
    const auto withinDepth = [&](bool walking) { return walking ? ++interior.events <= kMaxInteriorEvents : bounces++ < maxDepth_; };
    for (;;) {
        Intersection it;
        ++raysTraced;
        // Inside a subsurface volume the distance to the next scattering is drawn first and the ray
        // traced only that far: most steps of a walk end before the boundary, without a hit.
        const bool inVolume = interior.inside && medium == &*interior.medium;
        const float tScatter = inVolume ? interior.medium->walkDistance(beta, rng) : kInf;
        const bool hit = geometry_.intersect(o, d, tScatter, time, it);
        if (medium) {
            const float tMax = hit ? it.t : kInf;
            const MediumEvent e = inVolume ? interior.medium->walkEvent(tScatter, tMax, beta) : medium->sample(o, d, tMax, hero, rng);
            ratio *= e.pdfRatio;
            const float meanRatio = (ratio.x + ratio.y + ratio.z) / 3;
            beta = beta * e.weight / meanRatio;
            ratio = ratio / meanRatio;
            if (isBlack(beta)) break;
            if (e.scattered) {
                if (!withinDepth(interior.inside)) break;
                const Vertex v{o + e.t * d, -d, nullptr, nullptr, medium, time, nullptr};
                // Inside a subsurface volume every shadow ray meets its boundary.
                if (!interior.inside) L += beta * sampleLight(v, rng, raysTraced);
                const float u1 = rng.uniform(), u2 = rng.uniform();
                const Vec3f wi = medium->phase().sample(d, u1, u2);  // weight 1: sampled exactly
                lastSpecular = false;
                lastPdf = medium->phase().evaluate(d, wi);
                lastP = v.p;
                o = v.p;
                d = wi;
                if (!(interior.inside ? survivesInside() : survives())) break;
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
        const bool hasInterior = it.material->hasInterior();
        const bool walking = hasInterior && interior.inside && dot(d, it.hit.ng) > 0;  // the boundary, from within
        if (!withinDepth(walking)) break;
        const Bsdf bsdf(it.hit, *it.material);
        const Vertex v{it.hit.p, -d, &it, &bsdf, medium, time, hasInterior ? &interior : nullptr};
        if (!it.material->isSpecular()) L += beta * sampleLight(v, rng, raysTraced);
        BsdfSample bs;
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!bsdf.sample(v.wo, uLobe, u1, u2, bs) || isBlack(bs.weight)) break;
        beta *= bs.weight;
        lastSpecular = bs.specular;
        lastPdf = bs.pdf;
        lastP = it.hit.p;
        medium = hasInterior ? interior.cross(it, d, bs.wi, medium) : v.mediumToward(bs.wi);
        o = offsetRayOrigin(it.hit, bs.wi);
        d = bs.wi;
        if (!(interior.inside ? survivesInside() : survives())) break;
    }
    return allFinite(L) ? L : Vec3f{};
}

}  // namespace lenslab
