#include "materials/MicrofacetLobes.h"

#include <cmath>

#include "core/Pi.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

// Density of wi = reflect(wo, wh) given the density of wh: dwh/dwi = 1 / (4 |wo . wh|).
float reflectedPdf(const MicrofacetDistribution& d, Vec3f wo, Vec3f wh) {
    const float c = std::fabs(dot(wo, wh));
    return c > 0 ? d.pdf(wo, wh) / (4.0f * c) : 0.0f;
}

// A reflected direction about a sampled microfacet normal, on wo's side.
bool sampleReflection(const MicrofacetDistribution& d, Vec3f wo, float u1, float u2, Vec3f& wi) {
    const Vec3f wh = d.sampleWh(wo, u1, u2);
    if (dot(wo, wh) <= 0) return false;
    wi = reflect(wo, wh);
    return sameHemisphere(wo, wi);
}

}  // namespace

Vec3f MicrofacetReflection::f(Vec3f wo, Vec3f wi) const {
    const float cosO = std::fabs(wo.z), cosI = std::fabs(wi.z);
    const Vec3f h = wo + wi;
    if (cosO == 0 || cosI == 0 || (h.x == 0 && h.y == 0 && h.z == 0)) return {};
    Vec3f wh = normalize(h);
    // Fresnel against the facet turned to the normal's side, so a dielectric seen from inside
    // reflects totally past the critical angle.
    if (wh.z < 0) wh = -wh;
    const float s = d_.D(wh) * d_.G(wo, wi) / (4.0f * cosI * cosO);
    return s * fresnel_.evaluate(dot(wi, wh));
}

float MicrofacetReflection::pdf(Vec3f wo, Vec3f wi) const {
    if (!sameHemisphere(wo, wi)) return 0;
    return reflectedPdf(d_, wo, normalize(wo + wi));
}

bool MicrofacetReflection::sample(Vec3f wo, float, float u1, float u2, LobeSample& s) const {
    if (!sampleReflection(d_, wo, u1, u2, s.wi)) return false;
    s.pdf = pdf(wo, s.wi);
    s.f = f(wo, s.wi);
    s.specular = false;
    return s.pdf > 0;
}

bool MicrofacetTransmission::halfVector(Vec3f wo, Vec3f wi, Vec3f& wh, float& eta) const {
    if (sameHemisphere(wo, wi) || wo.z == 0 || wi.z == 0) return false;
    eta = wo.z > 0 ? etaB_ / etaA_ : etaA_ / etaB_;
    const Vec3f h = wo + eta * wi;
    if (dot(h, h) == 0) return false;
    wh = normalize(h);
    if (wh.z * wo.z < 0) wh = -wh;  // on wo's side, like the facets sampleWh draws
    // A refracting facet faces wo and turns its back to wi.
    return dot(wo, wh) > 0 && dot(wi, wh) < 0;
}

Vec3f MicrofacetTransmission::f(Vec3f wo, Vec3f wi) const {
    Vec3f wh;
    float eta = 1;
    if (!halfVector(wo, wi, wh, eta)) return {};
    const float F = fresnelDielectric(dot(wo, wh) * (wh.z > 0 ? 1.0f : -1.0f), etaA_, etaB_);
    const float denom = dot(wo, wh) + eta * dot(wi, wh);
    // For radiance the eta^2 of the generalised half-vector Jacobian cancels against the
    // 1/eta^2 by which radiance changes across the boundary.
    const float v = (1.0f - F) * d_.D(wh) * d_.G(wo, wi) * std::fabs(dot(wi, wh)) * std::fabs(dot(wo, wh)) /
                    (std::fabs(wi.z) * std::fabs(wo.z) * denom * denom);
    return {v, v, v};
}

float MicrofacetTransmission::pdf(Vec3f wo, Vec3f wi) const {
    Vec3f wh;
    float eta = 1;
    if (!halfVector(wo, wi, wh, eta)) return 0;
    const float denom = dot(wo, wh) + eta * dot(wi, wh);
    const float dwhDwi = eta * eta * std::fabs(dot(wi, wh)) / (denom * denom);
    return d_.pdf(wo, wh) * dwhDwi;
}

bool MicrofacetTransmission::sample(Vec3f wo, float, float u1, float u2, LobeSample& s) const {
    if (wo.z == 0) return false;
    const Vec3f wh = d_.sampleWh(wo, u1, u2);
    if (dot(wo, wh) <= 0) return false;
    const float etaRatio = wo.z > 0 ? etaA_ / etaB_ : etaB_ / etaA_;  // wo's side over the far side
    if (!refract(wo, wh, etaRatio, s.wi)) return false;
    s.pdf = pdf(wo, s.wi);
    s.f = f(wo, s.wi);
    s.specular = false;
    return s.pdf > 0;
}

Vec3f FresnelBlend::f(Vec3f wo, Vec3f wi) const {
    const auto pow5 = [](float x) { return (x * x) * (x * x) * x; };
    const float cosI = std::fabs(wi.z), cosO = std::fabs(wo.z);
    const float shape = 28.0f / 23.0f * kInvPif * (1.0f - pow5(1.0f - 0.5f * cosI)) * (1.0f - pow5(1.0f - 0.5f * cosO));
    const Vec3f diffuse = shape * rd_ * (Vec3f{1, 1, 1} - rs_);
    const Vec3f h = wo + wi;
    if (h.x == 0 && h.y == 0 && h.z == 0) return {};
    const Vec3f wh = normalize(h);
    const float hi = std::fabs(dot(wi, wh));
    const float glossy = d_.D(wh) / (4.0f * hi * std::max(cosI, cosO));
    return diffuse + glossy * fresnelSchlick(hi, rs_);
}

float FresnelBlend::pdf(Vec3f wo, Vec3f wi) const {
    if (!sameHemisphere(wo, wi)) return 0;
    return 0.5f * (std::fabs(wi.z) * kInvPif + reflectedPdf(d_, wo, normalize(wo + wi)));
}

// Half the samples cosine-weighted for the diffuse base, half from the coat's facets.
bool FresnelBlend::sample(Vec3f wo, float uc, float u1, float u2, LobeSample& s) const {
    if (uc < 0.5f) {
        s.wi = cosineHemisphere(u1, u2);
        if (wo.z < 0) s.wi.z = -s.wi.z;
    } else if (!sampleReflection(d_, wo, u1, u2, s.wi)) {
        return false;
    }
    s.pdf = pdf(wo, s.wi);
    s.f = f(wo, s.wi);
    s.specular = false;
    return s.pdf > 0;
}

}  // namespace lenslab
