#include "integrators/DirectLight.h"

#include <cmath>

#include "sampling/Sampling.h"

namespace lenslab {

Vec3f offsetRayOrigin(const SurfaceHit& h, Vec3f w) {
    const float eps = 1e-4f * std::max(1.0f, maxComponent({std::fabs(h.p.x), std::fabs(h.p.y), std::fabs(h.p.z)}));
    return h.p + (dot(w, h.ng) > 0 ? eps : -eps) * h.ng;
}

Vec3f lightSampleEstimate(const SceneGeometry& geometry, const Intersection& it, const Bsdf& bsdf, Vec3f wo,
                          const Light& light, float choicePdf, float u1, float u2, LightSampleWeight weighting,
                          std::uint64_t& raysTraced) {
    LightSample ls;
    if (!(choicePdf > 0) || !light.sample(it.hit.p, u1, u2, ls) || isBlack(ls.radiance) || !(ls.pdf > 0)) return {};
    float bsdfPdf;
    const Vec3f f = bsdf.evaluate(wo, ls.wi, bsdfPdf);
    if (isBlack(f)) return {};
    const Vec3f o = offsetRayOrigin(it.hit, ls.wi);
    const float tMax = std::isinf(ls.distance) ? std::numeric_limits<float>::infinity() : ls.distance * (1.0f - 1e-3f);
    ++raysTraced;
    if (geometry.occluded(o, ls.wi, tMax, it.time)) return {};
    const float pdf = ls.pdf * choicePdf;
    const float w = ls.delta || weighting == LightSampleWeight::Alone ? 1.0f : powerHeuristic(pdf, bsdfPdf);
    return w * f * ls.radiance / pdf;
}

Vec3f bsdfSampleEstimate(const SceneGeometry& geometry, const Intersection& it, const Bsdf& bsdf, Vec3f wo,
                         const Light& light, float uLobe, float u1, float u2, std::uint64_t& raysTraced) {
    if (light.isDelta()) return {};
    BsdfSample bs;
    if (!bsdf.sample(wo, uLobe, u1, u2, bs) || bs.specular || isBlack(bs.weight)) return {};
    Intersection next;
    ++raysTraced;
    const bool hit =
        geometry.intersect(offsetRayOrigin(it.hit, bs.wi), bs.wi, std::numeric_limits<float>::infinity(), it.time, next);
    Vec3f Le;
    float lightPdf = 0;
    if (hit && next.light == &light) {
        Le = light.emitted(&next.hit, bs.wi);
        lightPdf = light.pdf(it.hit.p, bs.wi, &next.hit);
    } else if (!hit && light.isInfinite()) {
        Le = light.emitted(nullptr, bs.wi);
        lightPdf = light.pdf(it.hit.p, bs.wi, nullptr);
    }
    if (isBlack(Le)) return {};
    return powerHeuristic(bs.pdf, lightPdf) * bs.weight * Le;
}

Vec3f environmentRadiance(const SceneGeometry& geometry, Vec3f d) {
    Vec3f L;
    for (const auto& light : geometry.lights())
        if (light->isInfinite()) L += light->emitted(nullptr, d);
    return L;
}

}  // namespace lenslab
