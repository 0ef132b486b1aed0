#include "materials/Microfacet.h"

#include <cmath>

#include "core/Pi.h"

namespace lenslab {

namespace {

// Trowbridge-Reitz visible normals for wo in the upper hemisphere (Heitz, "Sampling the GGX
// Distribution of Visible Normals", JCGT 7(4), 2018): stretch wo to the unit-roughness
// configuration, sample the projected hemisphere there, unstretch the normal.
Vec3f sampleVisibleTrowbridgeReitz(Vec3f wo, float ax, float ay, float u1, float u2) {
    const Vec3f vh = normalize(Vec3f{ax * wo.x, ay * wo.y, wo.z});
    const float len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3f t1 = len2 > 0 ? Vec3f{-vh.y, vh.x, 0} / std::sqrt(len2) : Vec3f{1, 0, 0};
    const Vec3f t2 = cross(vh, t1);
    const float r = std::sqrt(u1), phi = 2.0f * kPif * u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const Vec3f nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return normalize(Vec3f{ax * nh.x, ay * nh.y, std::max(1e-6f, nh.z)});
}

// Beckmann normals with density D(wh) cos(theta_h): the slopes are Gaussian with standard
// deviation alpha / sqrt(2) per axis (Box-Muller).
Vec3f sampleBeckmann(float ax, float ay, float u1, float u2) {
    const float r = std::sqrt(-std::log(std::max(1.0f - u1, 1e-12f))), phi = 2.0f * kPif * u2;
    return normalize(Vec3f{-ax * r * std::cos(phi), -ay * r * std::sin(phi), 1.0f});
}

}  // namespace

float roughnessToAlpha(float roughness) {
    const float x = std::log(std::max(roughness, 1e-3f));
    return 1.62142f + 0.819955f * x + 0.1734f * x * x + 0.0171201f * x * x * x + 0.000640711f * x * x * x * x;
}

MicrofacetDistribution::MicrofacetDistribution(MicrofacetKind kind, float alphaX, float alphaY)
    : kind_(kind), alphaX_(std::max(alphaX, 1e-3f)), alphaY_(std::max(alphaY, 1e-3f)) {}

float MicrofacetDistribution::D(Vec3f wh) const {
    const float z2 = wh.z * wh.z;
    if (z2 == 0) return 0;
    // e = tan^2(theta) (cos^2(phi) / ax^2 + sin^2(phi) / ay^2), written with the components.
    const float e = (wh.x * wh.x / (alphaX_ * alphaX_) + wh.y * wh.y / (alphaY_ * alphaY_)) / z2;
    const float norm = kPif * alphaX_ * alphaY_ * z2 * z2;
    if (kind_ == MicrofacetKind::Beckmann) return std::exp(-e) / norm;
    return 1.0f / (norm * (1.0f + e) * (1.0f + e));
}

float MicrofacetDistribution::lambda(Vec3f w) const {
    const float z2 = w.z * w.z;
    if (z2 == 0) return 0;
    // alpha(phi)^2 tan^2(theta) for the direction's azimuth.
    const float a2t2 = (alphaX_ * alphaX_ * w.x * w.x + alphaY_ * alphaY_ * w.y * w.y) / z2;
    if (kind_ == MicrofacetKind::TrowbridgeReitz) return 0.5f * (-1.0f + std::sqrt(1.0f + a2t2));
    if (a2t2 == 0) return 0;
    const float a = 1.0f / std::sqrt(a2t2);
    return 0.5f * (std::erf(a) - 1.0f) + std::exp(-a * a) / (2.0f * a * std::sqrt(kPif));
}

Vec3f MicrofacetDistribution::sampleWh(Vec3f wo, float u1, float u2) const {
    const bool below = wo.z < 0;
    Vec3f wh = kind_ == MicrofacetKind::TrowbridgeReitz
                   ? sampleVisibleTrowbridgeReitz(below ? -wo : wo, alphaX_, alphaY_, u1, u2)
                   : sampleBeckmann(alphaX_, alphaY_, u1, u2);
    return below ? -wh : wh;
}

float MicrofacetDistribution::pdf(Vec3f wo, Vec3f wh) const {
    if (kind_ == MicrofacetKind::Beckmann) return D(wh) * std::fabs(wh.z);
    if (wo.z == 0) return 0;
    return D(wh) * G1(wo) * std::fabs(dot(wo, wh)) / std::fabs(wo.z);
}

}  // namespace lenslab
