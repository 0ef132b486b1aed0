#include "materials/DiffuseLobes.h"

#include "core/Pi.h"
#include "materials/Fresnel.h"

#include <cmath>

#include "sampling/Sampling.h"

namespace lenslab {

namespace {

}  // namespace

Vec3f LambertianReflection::f(Vec3f, Vec3f) const { return {kInvPif, kInvPif, kInvPif}; }

Vec3f LambertianTransmission::f(Vec3f, Vec3f) const { return {kInvPif, kInvPif, kInvPif}; }

float LambertianTransmission::pdf(Vec3f wo, Vec3f wi) const {
    return sameHemisphere(wo, wi) ? 0.0f : std::fabs(wi.z) * kInvPif;
}

bool LambertianTransmission::sample(Vec3f wo, float, float u1, float u2, LobeSample& s) const {
    s.wi = cosineHemisphere(u1, u2);
    if (wo.z > 0) s.wi.z = -s.wi.z;
    s.pdf = pdf(wo, s.wi);
    s.f = f(wo, s.wi);
    s.specular = false;
    return s.pdf > 0;
}

OrenNayar::OrenNayar(float sigmaDegrees) {
    const float sigma = sigmaDegrees * float(M_PI) / 180.0f, s2 = sigma * sigma;
    a_ = 1.0f - s2 / (2.0f * (s2 + 0.33f));
    b_ = 0.45f * s2 / (s2 + 0.09f);
}

// f = (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)) / pi with alpha the larger and
// beta the smaller of the two polar angles.
Vec3f OrenNayar::f(Vec3f wo, Vec3f wi) const {
    const float sinI = std::sqrt(std::max(0.0f, 1.0f - wi.z * wi.z));
    const float sinO = std::sqrt(std::max(0.0f, 1.0f - wo.z * wo.z));
    float cosDeltaPhi = 0;
    if (sinI > 1e-4f && sinO > 1e-4f) cosDeltaPhi = std::max(0.0f, (wi.x * wo.x + wi.y * wo.y) / (sinI * sinO));
    const bool iSteeper = std::fabs(wi.z) > std::fabs(wo.z);
    const float sinAlpha = iSteeper ? sinO : sinI;
    const float tanBeta = iSteeper ? sinI / std::fabs(wi.z) : sinO / std::fabs(wo.z);
    const float v = kInvPif * (a_ + b_ * cosDeltaPhi * sinAlpha * tanBeta);
    return {v, v, v};
}

float CoatedDiffuse::throughCoat(float cosOutside) const {
    const float c = std::fabs(cosOutside);
    const float transmitted = 1 - fresnelDielectric(c, 1.0f, eta_);
    const float cosInside = std::sqrt(std::max(0.0f, 1 - (1 - c * c) / (eta_ * eta_)));
    return transmitted * (thickness_ > 0 && cosInside > 0 ? std::exp(-thickness_ / cosInside) : 1.0f);
}

Vec3f CoatedDiffuse::f(Vec3f wo, Vec3f wi) const {
    if (!sameHemisphere(wo, wi)) return {};
    const float k = throughCoat(wo.z) * throughCoat(wi.z) / (float(M_PI) * eta_ * eta_);
    const Vec3f r = reflectance_;
    return {k * r.x / (1 - r.x * internal_), k * r.y / (1 - r.y * internal_), k * r.z / (1 - r.z * internal_)};
}

float coatInternalReflectance(float eta) {
    // Fdr outside = 2 * integral of F(mu) mu dmu over [0, 1], by the midpoint rule.
    constexpr int kSteps = 256;
    double outside = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        outside += 2 * fresnelDielectric(float(mu), 1.0f, eta) * mu / kSteps;
    }
    return float(1 - (1 - outside) / (eta * eta));
}

}  // namespace lenslab
